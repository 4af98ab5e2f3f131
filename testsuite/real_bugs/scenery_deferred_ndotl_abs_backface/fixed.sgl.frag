#version 450
#include <safegi/prelude.sgl>
// A deferred renderer's point-light pass: the diffuse cosine is clamped at
// zero, so a surface facing away from the light receives nothing from it.
space world;

uniform sampler2D<point<world>> gPosition;
uniform sampler2D<normal<world>> gNormal;
uniform sampler2D gAlbedo;
uniform point<world> lightPos;
uniform spectrum<intensity> lightIntensity;

in vec2 textureCoord;
out vec4 fragColor;

void main() {
    point<world> FragPos = texture(gPosition, textureCoord).xyz;
    normal<world> N = normalize(texture(gNormal, textureCoord).xyz);
    spectrum<1> albedo = spectrum<1>(texture(gAlbedo, textureCoord).rgb);
    vector<world> toLight = lightPos - FragPos;
    float<length> d = length(toLight);
    direction<world> L = normalize(toLight);
    float<proj> NdotL = max(dot(L, N), 0.0);
    spectrum<irradiance> E = lightIntensity * inverse_square(d) * NdotL;
    spectrum<radiance> Lo = albedo / float<projected_solid_angle>(3.14159265) * E;
    fragColor = vec4(Lo, 1.0);
}
