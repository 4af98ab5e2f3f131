#version 450
#include <safegi/prelude.sgl>
// A material library's generated fragment shader, direct light on the Burley
// (Disney) diffuse lobe: the lobe is the Lambert 1/pi times the two Fresnel-
// like retro-reflection factors; radiance is albedo times lobe times the
// light's irradiance times the cosine.
space world;

uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<1> albedo;
uniform float<1> roughness;
uniform point<world> cameraPos;

in point<world, shaded> worldPos;
in normal<world> worldNormal;
out vec4 fragColor;

float<brdf> burleyDiffuse(float<proj> NdotL, float<proj> NdotV, float LdotH, float<1> r) {
    float F90 = 0.5 + 2.0 * r * LdotH * LdotH;
    float refL = 1.0 + (F90 - 1.0) * pow(1.0 - NdotL, 5.0);
    float refV = 1.0 + (F90 - 1.0) * pow(1.0 - NdotV, 5.0);
    return refL * refV / 3.14159265;
}

void main() {
    vec3 N = normalize(worldNormal);
    vec3 V = normalize(cameraPos - worldPos);
    vec3 H = normalize(lightDir + V);
    float NdotL = max(dot(N, lightDir), 0.0);
    float NdotV = max(dot(N, V), 0.0);
    float LdotH = max(dot(lightDir, H), 0.0);
    float fd = burleyDiffuse(NdotL, NdotV, LdotH, roughness);
    spectrum<radiance> Lo = albedo * fd * lightIrradiance * NdotL * 3.14159265;
    fragColor = vec4(Lo, 1.0);
}
