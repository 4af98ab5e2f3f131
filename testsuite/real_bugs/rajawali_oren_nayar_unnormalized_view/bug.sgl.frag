#version 330 core
#include <safegi/prelude.sgl>
// A mobile 3D engine's Oren-Nayar diffuse material: the eye vector arrives in
// view space and is rotated to world space; after that multiplication it
// must be normalised again before it enters the cosines of the model.
space world;
space view;

uniform rigidmap<view, world> uInverseViewRotation;
uniform direction<world> uLightDirection;             // toward the light
uniform spectrum<irradiance / proj> uLightColor;      // on a surface facing the light
uniform spectrum<1> uDiffuseColor;
uniform float<1> uRoughness;

in vector<view, toward> vEyeDir;                       // from the eye toward the surface
in normal<world> vNormal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(vNormal);
    direction<world, toward> viewDir = uInverseViewRotation * vEyeDir;
    float NdotL = max(dot(N, uLightDirection), 0.0);
    float NdotV = max(dot(N, -viewDir), 0.0);
    float sigma2 = uRoughness * uRoughness;
    float A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    float gamma = dot(-viewDir - N * NdotV, uLightDirection - N * NdotL);
    float alpha = max(acos(NdotV), acos(NdotL));
    float beta = min(acos(NdotV), acos(NdotL));
    float C = sin(alpha) * tan(beta);
    spectrum<radiance> color = uDiffuseColor * INV_PI * (A + B * max(0.0, gamma) * C) * uLightColor * NdotL;
    fragColor = vec4(color, 1.0);
}
