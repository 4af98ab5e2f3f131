#version 330 core
#include <safegi/prelude.sgl>
// A retro-style lit material that does its own vertex transform (the
// engine's is skipped): the position goes to view space by the model-view
// matrix, and the normal must go with it, since the lighting that follows is
// done in view space. The model-view matrix is taken as rigid (no scaling),
// so the normal goes through it as a direction.
space object;
space view;
space clip;

uniform rigidmap<object, view> modelView;
uniform projmap<view, clip> projection;

in point<object> vertex;
in normal<object> normalIn;
out normal<view> vNormal;

void main() {
    vec3 viewPos = (modelView * vec4(vertex, 1.0)).xyz;
    vNormal = normalize((modelView * vec4(normalIn, 0.0)).xyz);
    gl_Position = projection * vec4(viewPos, 1.0);
}
