#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
uniform float<area> A;
uniform float<length> d;
void main() {
  float<solid_angle> w = float<solid_angle>(A / (d * d));
  int n = 3;
  float<1> f = float<1>(n);
  c = vec4(w * f);
}
