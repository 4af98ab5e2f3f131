#version 330 core
#include <safegi/prelude.sgl>
// A projmap also takes homogeneous points: a jitter after the projection.
space view;
space clip;
uniform projmap<view, clip> clipFromView;
uniform projmap<clip, clip> jitter;
in point<view> p;
void main() {
  hpoint<clip> h = clipFromView * p;
  hpoint<clip> a = jitter * h;
  hpoint<clip> b = project(jitter, h);
  gl_Position = a + b;
}
