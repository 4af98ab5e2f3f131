#version 300 es
#include <safegi/prelude.sgl>
// A web engine's skinned vertex shader with a tangent frame for normal
// mapping: by the engine's convention the bones are rigid, so the normal and
// the tangent are both carried by the blended bone matrix as directions, then
// to view space (normal by the normal matrix, tangent by the model-view map).
precision highp float;
space bind;
space object;
space view;
space clip;

uniform mat4 boneMatrices[64];                    // bind pose -> object, per bone
uniform map<object, view> modelViewMatrix;
uniform mat3<object, view, normal> normalMatrix;
uniform projmap<view, clip> projectionMatrix;

in point<bind> position;
in normal<bind> objectNormal;
in direction<bind> objectTangent;
in vec4 skinIndex;
in vec4 skinWeight;
out normal<view> vNormal;
out direction<view> vTangent;

void main() {
    rigidmap<bind, object> skinMatrix =
        skinWeight.x * boneMatrices[int(skinIndex.x)] +
        skinWeight.y * boneMatrices[int(skinIndex.y)] +
        skinWeight.z * boneMatrices[int(skinIndex.z)] +
        skinWeight.w * boneMatrices[int(skinIndex.w)];
    vec3 skinnedNormal = (skinMatrix * vec4(objectNormal, 0.0)).xyz;
    vec3 skinnedTangent = skinnedNormal;
    vec4 skinned = skinMatrix * vec4(position, 1.0);
    vNormal = normalize(normalMatrix * skinnedNormal);
    vTangent = normalize((modelViewMatrix * vec4(skinnedTangent, 0.0)).xyz);
    gl_Position = projectionMatrix * (modelViewMatrix * skinned);
}
