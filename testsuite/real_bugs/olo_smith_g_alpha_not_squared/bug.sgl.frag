#version 450
#include <safegi/prelude.sgl>
// An engine's PBR include: GGX D and the height-correlated Smith visibility
// must describe the same surface, so both take alpha = roughness^2 and use
// alpha^2 (the Filament/Heitz form of the visibility term).
space world;

uniform point<world> u_CameraPosition;
uniform direction<world, away> u_LightDirection;       // toward the light
uniform spectrum<irradiance / proj> u_LightColor;      // on a surface facing the light
uniform spectrum<1> u_F0;
uniform float<1> u_Roughness;                          // artist-facing (perceptual)

layout(location = 0) in point<world, shaded> v_WorldPos;
layout(location = 1) in normal<world> v_Normal;
layout(location = 0) out vec4 o_Color;

const float PI = 3.141592653589793;

float distributionGGX(float NdotH, float roughness) {
    float a = roughness * roughness;
    float a2 = a * a;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

float geometrySmithHeightCorrelated(float NdotV, float NdotL, float roughness) {
    float a2 = roughness * roughness;
    float ggxV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float ggxL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return 0.5 / max(ggxV + ggxL, 1e-5);
}

void main() {
    vec3 N = normalize(v_Normal);
    vec3 V = normalize(u_CameraPosition - v_WorldPos);
    vec3 L = u_LightDirection;
    vec3 H = normalize(V + L);
    float NdotL = max(dot(N, L), 0.0);
    float NdotV = max(dot(N, V), 1e-4);
    float NdotH = max(dot(N, H), 0.0);
    float D = distributionGGX(NdotH, u_Roughness);
    float Vis = geometrySmithHeightCorrelated(NdotV, NdotL, u_Roughness);
    spectrum<1> F = u_F0 + (vec3(1.0) - u_F0) * pow(1.0 - max(dot(V, H), 0.0), 5.0);
    spectrum<radiance> Lo = float<brdf>(D * Vis) * F * u_LightColor * NdotL;
    o_Color = vec4(Lo, 1.0);
}
