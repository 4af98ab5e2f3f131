#version 330 core
#include <safegi/prelude.sgl>
// A mesh editor's preview shader lights in view space: positions go there by
// the model-view matrix, normals by its normal matrix (the inverse transpose
// of its linear part, computed once from the uniform), which keeps them
// perpendicular to the surface when the model is scaled non-uniformly.
space object;
space view;
space clip;

uniform map<object, view> matModelView;
uniform projmap<view, clip> matProjection;
uniform mat3<object, view, normal> mv_normalMatrix;

in point<object> vertexPosition;
in normal<object> vertexNormal;
out point<view> viewPosition;
out normal<view> viewNormal;

void main() {
    vec4 pos = matModelView * vec4(vertexPosition, 1.0);
    viewPosition = pos.xyz;
    viewNormal = normalize(mv_normalMatrix * vertexNormal);
    gl_Position = matProjection * pos;
}
