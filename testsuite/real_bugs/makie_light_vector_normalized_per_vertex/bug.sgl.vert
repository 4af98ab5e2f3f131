#version 330 core
#include <safegi/prelude.sgl>
// Vertex stage of a plotting library's mesh shader: the vector from the vertex
// to a point light is interpolated over the triangle and normalized per
// fragment, so it must leave this stage with its length.
space object;
space world;
space view;
space clip;

uniform map<object, world> model;
uniform map<world, view> view;
uniform projmap<view, clip> projection;
uniform point<world> lightposition;

in point<object> position;
out vector<view> o_lightdir;

void main() {
    vec4 view_pos = view * model * vec4(position, 1.0);
    gl_Position = projection * view_pos;
    vec4 view_light_pos = view * vec4(lightposition, 1.0);
    o_lightdir = normalize(view * vec4(lightposition, 1.0) - view_pos).xyz;
}
