#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<radiance> L;
out vec4 c;
void main() {
  float<radiance> r = L.r;
  float<radiance> g = L.g;
  c = vec4(r + g);
}
