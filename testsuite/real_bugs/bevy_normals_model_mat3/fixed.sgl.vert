#version 450
#include <safegi/prelude.sgl>
// A game engine's PBR vertex shader hands the fragment stage a world-space
// position and normal; the normal is carried by the transposed inverse of the
// model matrix, so non-uniformly scaled meshes are lit correctly.
space object;
space world;
space clip;

layout(set = 0, binding = 0) uniform CameraViewProj {
    projmap<world, clip> ViewProj;
};
layout(set = 1, binding = 0) uniform Transform {
    map<object, world> Model;
};

layout(location = 0) in point<object> Vertex_Position;
layout(location = 1) in normal<object> Vertex_Normal;
layout(location = 0) out point<world> v_WorldPosition;
layout(location = 1) out normal<world> v_WorldNormal;

void main() {
    vec4 world_position = Model * vec4(Vertex_Position, 1.0);
    v_WorldPosition = world_position.xyz;
    v_WorldNormal = mat3(transpose(inverse(Model))) * Vertex_Normal;
    gl_Position = ViewProj * world_position;
}
