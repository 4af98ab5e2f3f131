#version 330 core
#include <safegi/prelude.sgl>
space world;
space clip;
uniform projmap<world, clip> P;
uniform point<world> p;
out vec4 c;
void main() {
  point<clip> q = P * p;
  c = vec4(q, 1.0);
}
