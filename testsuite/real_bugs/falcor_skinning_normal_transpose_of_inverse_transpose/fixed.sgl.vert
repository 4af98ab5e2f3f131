#version 450
#include <safegi/prelude.sgl>
// A research renderer's skinning pass: each vertex blends the matrices of its
// bones into one bind-pose-to-object map; the position goes through that map,
// and the normal through the inverse transpose of its linear part, which the
// pass computes once per vertex for the purpose.
space bind;
space object;
space clip;

layout(std140, binding = 0) uniform Bones {
    mat4 boneMatrices[64];                       // bind pose -> object, per bone
};
uniform projmap<object, clip> clipFromObject;

layout(location = 0) in point<bind> bindPosition;
layout(location = 1) in normal<bind> bindNormal;
layout(location = 2) in uvec4 boneIds;
layout(location = 3) in vec4 boneWeights;
layout(location = 0) out normal<object> skinnedNormal;

void main() {
    map<bind, object> blendedMat =
        boneWeights.x * boneMatrices[boneIds.x] +
        boneWeights.y * boneMatrices[boneIds.y] +
        boneWeights.z * boneMatrices[boneIds.z] +
        boneWeights.w * boneMatrices[boneIds.w];
    mat3 invTransposeMat = transpose(inverse(mat3(blendedMat)));
    vec4 skinnedPosition = blendedMat * vec4(bindPosition, 1.0);
    skinnedNormal = normalize(invTransposeMat * bindNormal);
    gl_Position = clipFromObject * skinnedPosition;
}
