#version 330 core
#include <safegi/prelude.sgl>
// A PBS material: direct lights use the diffuse BRDF (albedo / pi), but the
// irradiance probe already holds the cosine-weighted average of incoming
// radiance, which is reflected by the albedo alone.
space world;

uniform point<world> lightPos;
uniform spectrum<intensity> lightColour;
uniform samplerCube<spectrum<radiance>> irradianceProbe;  // cosine-convolved environment (E / pi)
uniform spectrum<1> kD;                                    // diffuse albedo

in point<world, shaded> worldPos;
in normal<world> worldNormal;
out vec4 outColour;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(worldNormal);
    vec3 diffuse = kD * INV_PI;                  // pixelData.diffuse
    vec3 toLight = lightPos - worldPos;
    float d = length(toLight);
    vec3 L = normalize(toLight);
    float NdotL = max(dot(N, L), 0.0);
    float falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> finalColour = diffuse * lightColour * falloff * NdotL;
    vec3 envColourIrradiance = texture(irradianceProbe, N).rgb;
    finalColour += envColourIrradiance * diffuse;
    outColour = vec4(finalColour, 1.0);
}
