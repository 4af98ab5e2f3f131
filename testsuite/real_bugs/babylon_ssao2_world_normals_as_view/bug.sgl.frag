#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// A web engine's SSAO2 post-process: the hemisphere of samples around a pixel
// is oriented by a tangent frame built around the pixel's view-space normal.
// When the geometry buffer stores world-space normals, the sampled normal is
// first carried to view space by the view's normal matrix (a 3x3 uniform
// computed on the CPU).
space world;
space view;
space clip;
space tangent_s;

uniform sampler2D<normal<world>> normalSampler;       // world-space normals
uniform sampler2D<point<view>> positionSampler;        // view-space positions
uniform sampler2D<float<length>> depthSampler;         // linear view depth
uniform sampler2D randomSampler;
uniform mat3<world, view, normal> viewNormalMatrix;
uniform projmap<view, clip> projection;
uniform vec3 sampleSphere[16];
uniform float<length> radius;
uniform float<length> base;
uniform float<1> totalStrength;
uniform vec2 randTextureTiles;

in vec2 vUV;
out vec4 fragColor;

void main() {
    point<view> origin = texture(positionSampler, vUV).xyz;
    vec3 normalWorld = normalize(texture(normalSampler, vUV).xyz);
    vec3 n = normalWorld;
    vec3 rvec = texture(randomSampler, vUV * randTextureTiles).xyz * 2.0 - 1.0;
    vec3 tangent = normalize(rvec - n * dot(rvec, n));
    vec3 bitangent = cross(n, tangent);
    mat3<tangent_s, view, rigid> tbn = mat3(tangent, bitangent, n);
    float occlusion = 0.0;
    for (int i = 0; i < 16; i++) {
        point<view> samplePos = origin + (tbn * sampleSphere[i]) * radius;
        vec4 offset = projection * vec4(samplePos, 1.0);
        vec2 sampleUV = offset.xy / offset.w * 0.5 + 0.5;
        float<length> sampleDepth = texture(depthSampler, sampleUV).r;
        if (sampleDepth < samplePos.z - base) {
            occlusion += 1.0;
        }
    }
    fragColor = vec4(vec3(1.0 - totalStrength * occlusion / 16.0), 1.0);
}
