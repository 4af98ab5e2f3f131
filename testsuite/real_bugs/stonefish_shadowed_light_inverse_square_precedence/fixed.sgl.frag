#version 330 core
#include <safegi/prelude.sgl>
// Shadowed point light of a simulator's renderer: Lambert reflection of a
// point light whose irradiance falls off with the inverse square of the
// distance (the shadow test is a caller's factor here).
space world;

uniform point<world> lightPosition;
uniform spectrum<intensity> lightColor;
uniform spectrum<1> albedo;
uniform float<1> shadowFactor;

in point<world, shaded> P;
in normal<world> vNormal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

spectrum<radiance> shadowedPointLight(normal<world> N) {
    vec3 toLight = lightPosition - P;
    float distance = length(toLight);
    vec3 L = toLight / distance;
    float NdotL = max(dot(N, L), 0.0);
    //Inverse square law
    float attenuation = float<solid_angle / (area * proj)>(1.0 / (distance * distance));
    return albedo * INV_PI * lightColor * attenuation * NdotL * shadowFactor;
}

void main() {
    spectrum<radiance> L = shadowedPointLight(normalize(vNormal));
    fragColor = vec4(L, 1.0);
}
