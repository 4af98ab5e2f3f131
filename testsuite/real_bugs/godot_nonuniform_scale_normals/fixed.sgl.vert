#version 330 core
#include <safegi/prelude.sgl>
// An engine's scene vertex shader: positions go through the model matrix,
// normals through its inverse transpose, which the renderer uploads as
// model_normal_matrix so that non-uniformly scaled meshes keep their normals
// perpendicular to the surface.
space object;
space world;
space view;
space clip;

uniform map<object, world> model_matrix;
uniform mat3 model_normal_matrix;                 // transpose(inverse(mat3(model_matrix)))
uniform rigidmap<world, view> view_matrix;
uniform projmap<view, clip> projection_matrix;

in point<object> vertex_attrib;
in normal<object> normal_attrib;
out point<view> vertex_interp;
out normal<view> normal_interp;

void main() {
    vec3 vertex = (model_matrix * vec4(vertex_attrib, 1.0)).xyz;
    vec3 normal = model_normal_matrix * normal_attrib;
    vertex_interp = (view_matrix * vec4(vertex, 1.0)).xyz;
    normal_interp = normalize(mat3(view_matrix) * normal);
    gl_Position = projection_matrix * vec4(vertex_interp, 1.0);
}
