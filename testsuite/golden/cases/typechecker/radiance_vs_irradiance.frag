#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<irradiance> E;
out vec4 c;
void main() {
  spectrum<radiance> L = E;
  c = vec4(L, 1.0);
}
