#version 330 core
// Direct illumination from a point light on a diffuse surface: intensity,
// inverse-square falloff, the cosine projection, and the BRDF.
#include <safegi/prelude.sgl>

space world;

uniform point<world>        lightPos;
uniform spectrum<intensity> lightI;        // W / sr
uniform spectrum<brdf>      Kd;            // albedo / pi

in point<world>  P;
in normal<world> N;

out vec4 fragColor;

void main() {
    vector<world> toLight = lightPos - P;
    float<length> d = length(toLight);
    direction<world> wi = normalize(toLight);
    float<proj> cosTheta = max(dot(normalize(N), wi), 0.0);
    // 1/d^2 is the solid angle per unit projected area the light sees the
    // surface under: solid_angle / (area * proj), the inverse-square law.
    float<solid_angle / (area * proj)> G = inverse_square(d);
    spectrum<radiance> L = Kd * lightI * cosTheta * G;
    fragColor = vec4(L, 1.0);
}
