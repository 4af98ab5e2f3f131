#version 450
#include <safegi/prelude.sgl>
// A game mod's PBR direct light, the diffuse lobes: the base, a wrapped
// subsurface lobe and a coat layer's diffuse are each Lambertian (albedo over
// pi) times the light's irradiance and their cosine-like factor.
space world;

const float PI = 3.14159265358979;

uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<1> baseColor;
uniform spectrum<1> subsurfaceColor;
uniform spectrum<1> coatColor;
uniform float<1> wrapAmount;

in normal<world> worldNormal;
out vec4 fragColor;

void main() {
    vec3 N = normalize(worldNormal);
    float NdotL = max(dot(N, lightDir), 0.0);
    float wrap = clamp((dot(N, lightDir) + wrapAmount) / (1.0 + wrapAmount), 0.0, 1.0);
    vec3 base = baseColor * lightIrradiance * NdotL / PI;
    vec3 sss = subsurfaceColor * lightIrradiance * wrap / PI;
    vec3 coat = coatColor * lightIrradiance * NdotL / PI;
    spectrum<radiance> Lo = base + sss + coat;
    fragColor = vec4(Lo, 1.0);
}
