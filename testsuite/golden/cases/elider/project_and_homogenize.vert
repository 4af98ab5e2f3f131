#version 330 core
#include <safegi/prelude.sgl>
space world;
space clip;
uniform projmap<world, clip> P;
in point<world> p;
out vec3 ndc;
void main() {
  hpoint<clip> h = P * p;
  point<clip> q = homogenize(h);
  ndc = q;
  gl_Position = h;
}
