#version 450
#include <safegi/prelude.sgl>
// A game-engine rebuild's direct light for legacy content: Lambert diffuse,
// the albedo (scaled by the diffuse weight) over pi, times the light's
// irradiance and the cosine.
space world;

const float PI = 3.14159265358979;

uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<1> albedo;
uniform float<1> kD;

in normal<world> vNormal;
out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormal);
    float NdotL = max(dot(N, lightDir), 0.0);
    vec3 diffuseBrdf = kD * albedo / PI;
    spectrum<radiance> Lo = diffuseBrdf * lightIrradiance * NdotL;
    fragColor = vec4(Lo, 1.0);
}
