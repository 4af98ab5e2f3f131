#version 330 core
#include <safegi/prelude.sgl>
uniform Light { spectrum<radiance> Le; float<area> A; } light;
out vec4 c;
void main() {
  float<time> t = light.A;
  c = vec4(t);
}
