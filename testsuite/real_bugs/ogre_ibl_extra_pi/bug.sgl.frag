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
    normal<world> N = normalize(worldNormal);
    spectrum<brdf> diffuse = kD * INV_PI;                  // pixelData.diffuse
    vector<world, away> toLight = lightPos - worldPos;
    float<length> d = length(toLight);
    direction<world, away> L = normalize(toLight);
    float<proj> NdotL = max(dot(N, L), 0.0);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> finalColour = diffuse * lightColour * falloff * NdotL;
    spectrum<radiance> envColourIrradiance = texture(irradianceProbe, N).rgb;
    finalColour += envColourIrradiance * diffuse;
    outColour = vec4(finalColour, 1.0);
}
