#version 300 es
#include <safegi/prelude.sgl>
// A real-time PBR engine's vertex stage without normal mapping: the mesh
// normal is first skinned (the bones carry the bind pose to the posed model),
// then brought to world space by the object's normal matrix.
precision highp float;
space bind;
space model;
space world;
space clip;

uniform mat3 boneNormalMatrices[64];              // bind pose -> model, per bone
uniform mat3<model, world, normal> worldFromModelNormalMatrix;
uniform map<bind, world> worldFromBindMatrix;     // blended on the CPU for positions
uniform projmap<world, clip> clipFromWorldMatrix;

in point<bind> mesh_position;
in normal<bind> mesh_normal;
in uvec4 mesh_bone_indices;
in vec4 mesh_bone_weights;
out normal<world> vertex_worldNormal;

normal<model> skinNormal(normal<bind> n, uvec4 ids, vec4 weights) {
    mat3 m = weights.x * boneNormalMatrices[ids.x] + weights.y * boneNormalMatrices[ids.y] +
             weights.z * boneNormalMatrices[ids.z] + weights.w * boneNormalMatrices[ids.w];
    return normalize(m * n);
}

void main() {
    vec3 worldNormal = mesh_normal;
    worldNormal = skinNormal(worldNormal, mesh_bone_indices, mesh_bone_weights);
    worldNormal = worldFromModelNormalMatrix * worldNormal;
    vertex_worldNormal = normalize(worldNormal);
    gl_Position = clipFromWorldMatrix * (worldFromBindMatrix * vec4(mesh_position, 1.0));
}
