#version 330 core
#include <safegi/prelude.sgl>
uniform float<length> depths[4];
out vec4 c;
void main() {
  float<length> s = 0.0;
  for (int i = 0; i < 4; ++i) s += depths[i];
  c = vec4(s);
}
