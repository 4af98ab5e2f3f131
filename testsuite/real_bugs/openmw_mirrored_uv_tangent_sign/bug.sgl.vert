#version 330 core
#include <safegi/prelude.sgl>
// Vertex stage of normal-mapped objects: the tangent frame handed to the
// fragment stage; the tangent's w (+1 or -1) says whether the UVs are mirrored,
// which flips the bitangent.
space object;
space view;
space clip;

uniform map<object, view> modelView;
uniform mat3<object, view, normal> normalMatrix;
uniform projmap<view, clip> projection;

in point<object> position;
in normal<object> aNormal;
in vec4 tangent;
out mat3 normalToView;

void main() {
    vec3 N = normalize(normalMatrix * aNormal);
    vec3 T = normalize(mat3(modelView) * tangent.xyz);
    vec3 B = cross(N, T);
    normalToView = mat3(T, B, N);
    gl_Position = projection * modelView * vec4(position, 1.0);
}
