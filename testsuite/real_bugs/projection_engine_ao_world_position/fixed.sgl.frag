#version 300 es
#include <safegi/prelude.sgl>
// A web engine's screen-space ambient occlusion: the G-buffer stores world
// positions, while the kernel is oriented around the view-space normal and
// projected with the camera's projection, so the position is taken to view
// space first, for the fragment and for each sample's stored depth.
precision highp float;
space world;
space view;
space clip;

uniform sampler2D<point<world>> gPosition;
uniform sampler2D<normal<view>> gNormal;
uniform sampler2D noiseSampler;
uniform map<world, view> viewMatrix;
uniform projmap<view, clip> projectionMatrix;
uniform vec3 samples[16];                        // kernel, tangent space
uniform float<length> radius;

in vec2 texCoords;
out float fragAO;

void main() {
    vec3 fragPos = (viewMatrix * vec4(texture(gPosition, texCoords).xyz, 1.0)).xyz;
    vec3 N = normalize(texture(gNormal, texCoords).xyz);
    vec3 randomVec = normalize(texture(noiseSampler, texCoords * 4.0).xyz);
    vec3 T = normalize(randomVec - N * dot(randomVec, N));
    vec3 B = cross(N, T);
    mat3 TBN = mat3(T, B, N);
    float occlusion = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec3 samplePos = fragPos + TBN * samples[i] * radius;
        vec4 offset = projectionMatrix * vec4(samplePos, 1.0);
        vec2 uv = offset.xy / offset.w * 0.5 + 0.5;
        float sampleDepth = (viewMatrix * vec4(texture(gPosition, uv).xyz, 1.0)).z;
        occlusion += (sampleDepth >= samplePos.z + 0.025 ? 1.0 : 0.0);
    }
    fragAO = 1.0 - occlusion / 16.0;
}
