#version 330 core
#include <safegi/prelude.sgl>
// An industry PBR shading model's reference code: the base layer's diffuse
// BRDF is the albedo times the energy left after specular, divided by pi,
// lit by a punctual light's irradiance on the surface.
space world;

uniform point<world> lightPosition;
uniform spectrum<intensity> lightIntensity;
uniform spectrum<1> baseColor;
uniform float<1> specularAlbedo;          // directional albedo of the specular layer

in point<world, shaded> position;
in normal<world> normal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(normal);
    vec3 toLight = lightPosition - position;
    float d = length(toLight);
    vec3 L = normalize(toLight);
    float NdotL = max(dot(N, L), 0.0);
    spectrum<irradiance> E = lightIntensity * NdotL * inverse_square(d);
    spectrum<brdf> fDiffuse = baseColor * (1.0 - specularAlbedo) * INV_PI;
    spectrum<radiance> Lo = fDiffuse * E;
    fragColor = vec4(Lo, 1.0);
}
