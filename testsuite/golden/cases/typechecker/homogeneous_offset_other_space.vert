#version 330 core
#include <safegi/prelude.sgl>
// An offset added to a homogeneous point must be in its space: a view-space
// normal added to a clip-space position (a normal visualiser's end point) is
// told; added in view space before the projection it is right.
space view;
space clip;
uniform projmap<view, clip> projection;
in point<view> viewPos;
in normal<view> nor;
in hpoint<clip> pos;
void main() {
    vec4 tip = projection * (vec4(viewPos, 1.0) + vec4(nor * (0.1 * meter), 0.0));
    gl_Position = pos + vec4(nor * (0.1 * meter), 0.0);
    gl_Position = tip;
}
