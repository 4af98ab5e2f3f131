#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 0.0;
  spectrum<radiance> L = vec3(0.0);
  c = vec4(L * d, d);
}
