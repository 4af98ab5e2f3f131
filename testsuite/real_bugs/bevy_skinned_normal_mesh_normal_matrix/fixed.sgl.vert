#version 450
#include <safegi/prelude.sgl>
// A game engine's PBR vertex shader, skinned variant: the joint matrices
// (which include the entity's transform) carry the bind-pose vertex straight
// to world space, and the normal through the inverse transpose of the blended
// joint matrix. The mesh's own model matrix and normal matrix (local -> world)
// are still bound, for unskinned meshes.
space bind;
space local;
space world;
space clip;

layout(set = 0, binding = 0) uniform View {
    projmap<world, clip> view_proj;
};
layout(set = 2, binding = 0) uniform Mesh {
    map<local, world> model;
    mat3<local, world, normal> inverse_transpose_model;
};
layout(set = 2, binding = 1) uniform SkinnedMesh {
    mat4 joint_matrices[256];                    // bind pose -> world, per joint
};

layout(location = 0) in point<bind> Vertex_Position;
layout(location = 1) in normal<bind> Vertex_Normal;
layout(location = 2) in uvec4 Vertex_JointIndex;
layout(location = 3) in vec4 Vertex_JointWeight;
layout(location = 0) out point<world> v_WorldPosition;
layout(location = 1) out normal<world> v_WorldNormal;

void main() {
    map<bind, world> skin =
        Vertex_JointWeight.x * joint_matrices[Vertex_JointIndex.x] +
        Vertex_JointWeight.y * joint_matrices[Vertex_JointIndex.y] +
        Vertex_JointWeight.z * joint_matrices[Vertex_JointIndex.z] +
        Vertex_JointWeight.w * joint_matrices[Vertex_JointIndex.w];
    vec4 world_position = skin * vec4(Vertex_Position, 1.0);
    mat3 skinNormalMatrix = transpose(inverse(mat3(skin)));
    v_WorldPosition = world_position.xyz;
    v_WorldNormal = normalize(skinNormalMatrix * Vertex_Normal);
    gl_Position = view_proj * world_position;
}
