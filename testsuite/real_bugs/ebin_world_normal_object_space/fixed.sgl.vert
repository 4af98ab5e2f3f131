#version 330 core
#include <safegi/prelude.sgl>
// A block-game shader pack's main geometry pass: besides the view-space TBN it
// passes a world-space normal to the fragment stage (for waves and sky light).
// The vertex normal is in the model's own space; the normal matrix takes it to
// view space and the inverse view rotation on to world space.
space object;
space view;
space world;
space clip;

uniform map<object, view> modelViewMatrix;
uniform mat3<object, view, normal> normalMatrix;          // gl_NormalMatrix
uniform rigidmap<view, world> gbufferModelViewInverse;
uniform projmap<view, clip> projectionMatrix;

in point<object> vaPosition;
in normal<object> vaNormal;                               // gl_Normal
out normal<world> worldNormal;

void main() {
    gl_Position = projectionMatrix * modelViewMatrix * vec4(vaPosition, 1.0);
    worldNormal = mat3(gbufferModelViewInverse) * normalMatrix * normalize(vaNormal);
}
