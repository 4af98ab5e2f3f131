#version 330 core
#include <safegi/prelude.sgl>
// Direct illumination from a point light and from one sample of an area light.
space world;
space shape_s;

uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
uniform rigidmap<shape_s, world> worldFromShape;
uniform point<shape_s> lightSample;
uniform normal<shape_s> lightNormal;
uniform spectrum<radiance> Le;
uniform float<area> lightArea;
uniform spectrum<brdf> Kd;

in point<world> P;
in normal<world> N;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(N);

    // Point light: dω per unit projected area at distance d is 1/d².
    vector<world> toLight = lightPos - P;
    float<length> d = length(toLight);
    direction<world> wi = normalize(toLight);
    float<proj> cosTheta = max(dot(n, wi), 0.0);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> Lpoint = Kd * lightI * cosTheta * falloff;

    // Area light, one sample drawn uniformly by area.
    point<world> y = worldFromShape * lightSample;
    normal<world> ny = worldFromShape * lightNormal;
    vector<world> toY = y - P;
    float<length> r = length(toY);
    direction<world> wy = normalize(toY);
    float cosSurface = max(dot(n, wy), 0.0);
    float cosLight = max(dot(wy, ny), 0.0);
    float<pdf_area> pdfA = 1.0 / lightArea;
    float<pdf_solid_angle> pdfW = float<pdf_solid_angle>(pdfA * (r * r) / cosLight);
    spectrum<radiance> Larea = Kd * Le * cosSurface / pdfW;

    fragColor = vec4(Lpoint + Larea, 1.0);
}
