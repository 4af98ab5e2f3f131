#version 330 core
#include <safegi/prelude.sgl>
// The paper's area-light direct illumination: light samples in the light's
// shape space (point<shape_s>), a rigid map to world, pdfs by measure.
space world_s;
space shape_s;

const int SAMPLES = 4;
uniform rigidmap<shape_s, world_s> worldFromShape;
uniform point<shape_s> samples[SAMPLES];
uniform normal<shape_s> lightNormal;
uniform spectrum<radiance> Le;
uniform float<area> lightArea;
uniform spectrum<brdf> Kd;

in point<world_s> P;
in normal<world_s> N;
out vec4 fragColor;

void main() {
    normal<world_s> n = normalize(N);
    normal<world_s> ny = worldFromShape * lightNormal;
    float<pdf_area> pdfA = 1.0 / lightArea;
    spectrum<radiance> L = spectrum<radiance>(0.0);
    for (int i = 0; i < SAMPLES; ++i) {
        point<world_s> y = worldFromShape * samples[i];
        vector<world_s> toY = y - P;
        float<length> r = length(toY);
        direction<world_s> wy = normalize(toY);
        float<proj> cosSurface = max(dot(n, wy), 0.0);
        float<proj> cosLight = max(dot(-wy, ny), 0.0);
        // change of measure: p_ω = p_A · r² / cos θ_y
        float<pdf_solid_angle> pdfW = float<pdf_solid_angle>(pdfA * (r * r) / cosLight);
        L += Kd * Le * cosSurface / pdfW;
    }
    fragColor = vec4(L / float(SAMPLES), 1.0);
}
