#version 330 core
#include <safegi/prelude.sgl>
space world;
space clip;
uniform projmap<world, clip> P;
in point<world> p;
out vec3 ndc;
void main() {
  ndc = homogenize(project(P, p));
  gl_Position = vec4(ndc, 1.0);
}
