#version 330 core
#include <safegi/prelude.sgl>
// Point lights on team-coloured models: the light positions arrive in world
// space, the interpolated normal in view space; the normal is carried back to
// world space by the camera's (rigid) view-to-world rotation before any dot.
space world;
space view;

uniform rigidmap<view, world> cameraToWorld;
uniform point<world> pointLightPos;
uniform vec3 pointLightColor;
uniform float<length> pointLightRange;
uniform sampler2D diffuseTex;

in point<world, shaded> worldPos;
in normal<view> normalView;
in vec2 uv;
out vec4 fragColor;

void main() {
    vec3 N = normalize(normalView);
    vec3 toLight = pointLightPos - worldPos;
    float dist = length(toLight);
    vec3 L = normalize(toLight);
    float NdotL = max(dot(N, L), 0.0);
    float attenuation = clamp(1.0 - dist / pointLightRange, 0.0, 1.0);
    vec3 albedo = texture(diffuseTex, uv).rgb;
    vec3 lit = albedo * pointLightColor * NdotL * attenuation;
    fragColor = vec4(lit, 1.0);
}
