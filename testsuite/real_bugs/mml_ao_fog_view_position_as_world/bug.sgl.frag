#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// A web engine's ambient-occlusion compositor fades the occlusion with the
// scene's linear fog: the fragment's position is reconstructed from the depth
// buffer with the inverse projection (element by element, as the original
// does), carried to world space by the camera's world matrix, and its
// distance to the world-space camera position drives the fog.
space view : eye;
space world;

uniform sampler2D sceneDiffuse;
uniform sampler2D sceneDepth;
uniform sampler2D aoTexture;
uniform mat4 projectionMatrixInv;            // read element by element
uniform map<view, world> cameraMatrixWorld;
uniform point<world> cameraPos;
uniform float<length> fogNear;
uniform float<length> fogFar;

in vec2 vUv;
out vec4 fragColor;

point<world> getWorldPos(float depth, vec2 coord) {
    vec2 ndc = coord * 2.0 - 1.0;
    float ndcZ = depth * 2.0 - 1.0;
    mat4 Q = projectionMatrixInv;
    vec3 v = vec3(Q[0][0] * ndc.x + Q[3][0], Q[1][1] * ndc.y + Q[3][1], Q[3][2]);
    float invW = 1.0 / (Q[2][3] * ndcZ + Q[3][3]);
    point<view> viewPos = point<view>(v * invW);
    return viewPos;
}

void main() {
    float depth = texture(sceneDepth, vUv).r;
    point<world> worldPos = getWorldPos(depth, vUv);
    float<length> dist = distance(worldPos, cameraPos);
    float fogFactor = smoothstep(fogNear, fogFar, dist);
    float ao = mix(texture(aoTexture, vUv).r, 1.0, fogFactor);
    fragColor = vec4(texture(sceneDiffuse, vUv).rgb * ao, 1.0);
}
