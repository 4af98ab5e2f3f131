#version 330 core
#include <safegi/prelude.sgl>
// Irradiance from a point light, reflected radiance, and an ambient radiance term.
space world;

uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
uniform spectrum<brdf> Kd;
uniform spectrum<radiance> ambient;

in point<world> P;
in normal<world> N;
out vec4 fragColor;

void main() {
    vector<world> toLight = lightPos - P;
    float<length> d = length(toLight);
    float<proj> cosTheta = max(dot(normalize(N), normalize(toLight)), 0.0);
    // dω per unit projected area facing the light is 1/d²; the cosine projects it onto the surface.
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<irradiance> E = lightI * cosTheta * falloff;
    spectrum<radiance> L = Kd * E / 3.14159265;
    spectrum<radiance> total = L + ambient;
    fragColor = vec4(total, 1.0);
}
