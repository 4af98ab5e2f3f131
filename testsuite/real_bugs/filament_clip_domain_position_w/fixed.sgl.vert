#version 330 core
#include <safegi/prelude.sgl>
// An engine's vertex stage for materials whose vertex domain is clip space:
// the material hands over a clip-space position, and the world-space shading
// position the lighting needs is recovered through the inverse of the
// view-projection, which takes a perspective divide at the end.
space world;
space clip;

uniform projmap<clip, world> worldFromClipMatrix;

in hpoint<clip> mesh_position;              // the material's clip-space vertex
in vec2 mesh_uv0;
out point<world> vertex_worldPosition;
out vec2 vertex_uv01;

void main() {
    vec4 position = mesh_position;
    vec4 p = worldFromClipMatrix * position;
    vertex_worldPosition = p.xyz / p.w;
    vertex_uv01 = mesh_uv0;
    gl_Position = position;
}
