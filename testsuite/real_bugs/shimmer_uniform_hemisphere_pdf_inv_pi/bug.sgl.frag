#version 330 core
#include <safegi/prelude.sgl>
// A physically based renderer's sampling routines and a diffuse estimator
// that uses them: a direction drawn uniformly over the hemisphere has the
// density 1 / (2 pi) per steradian; 1 / pi is the constant of the
// cosine-weighted density, cos(theta) / pi.
space shading : frame;

const float<pdf_projected_solid_angle> INV_PI = float<pdf_projected_solid_angle>(0.3183098861837907);
const float<pdf_solid_angle> INV_2PI = float<pdf_solid_angle>(0.15915494309189535);

uniform samplerCube<spectrum<radiance>, shading> incident;
uniform spectrum<brdf> f;

in vec2 u;
in direction<shading, away> wo;
out vec4 fragColor;

float<pdf_solid_angle> uniformHemispherePdf() {
    return INV_PI;
}

float<pdf_solid_angle> cosineHemispherePdf(float<proj> cosTheta) {
    return cosTheta * INV_PI;
}

direction<shading> sampleUniformHemisphere(vec2 s) {
    float z = s.x;
    float r = sqrt(max(1.0 - z * z, 0.0));
    float phi = 6.283185307179586 * s.y;
    return direction<shading>(vec3(r * cos(phi), r * sin(phi), z));
}

void main() {
    direction<shading> wi = sampleUniformHemisphere(u);
    spectrum<radiance> Li = texture(incident, wi).rgb;
    spectrum<radiance> L = f * Li * abs(wi.z) / uniformHemispherePdf();
    fragColor = vec4(L, 1.0);
}
