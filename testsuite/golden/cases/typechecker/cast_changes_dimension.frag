#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<area> a = 2.0 * meter * meter;
  float<length> d = 3.0 * meter;
  float<solid_angle> w = float<solid_angle>(a / (d * d));
  c = vec4(w);
}
