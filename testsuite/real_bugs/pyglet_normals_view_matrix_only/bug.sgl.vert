#version 330 core
#include <safegi/prelude.sgl>
// A Python multimedia library's default lit-model shader: once models got a
// model matrix of their own, positions went to view space by view * model,
// and the normals, lit in view space, must follow by the normal matrix of
// that same model-view product.
space object;
space world;
space view;
space clip;

uniform WindowBlock {
    projmap<view, clip> projection;
    map<world, view> view;
} window;
uniform map<object, world> model;

in point<object> position;
in normal<object> normals;
out point<view> vertex_position;
out normal<view> vertex_normals;

void main() {
    mat4 modelview = window.view * model;
    vec4 pos = modelview * vec4(position, 1.0);
    gl_Position = window.projection * pos;
    mat3 normal_matrix = transpose(inverse(mat3(window.view)));
    vertex_position = pos.xyz;
    vertex_normals = normal_matrix * normals;
}
