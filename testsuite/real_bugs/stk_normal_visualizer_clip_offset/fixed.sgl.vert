#version 330 core
#include <safegi/prelude.sgl>
// A kart game's debug view draws each vertex normal as a short line; this
// stage places the line's far end. The vertex arrives already projected (the
// clip-space position the previous stage wrote), its normal in view space:
// the end point is found in view space, by undoing the projection and its
// divide, then projected again.
space view : eye;
space clip;

uniform projmap<view, clip> ProjectionMatrix;
uniform projmap<clip, view> InverseProjectionMatrix;

const float<length> kNormalLength = float<length>(0.2);

in hpoint<clip> pos;            // gl_in[i].gl_Position of the geometry stage
in normal<view> nor;

void main() {
    vec4 viewPos = InverseProjectionMatrix * pos;
    viewPos /= viewPos.w;
    gl_Position = ProjectionMatrix * (viewPos + vec4(nor * kNormalLength, 0.0));
}
