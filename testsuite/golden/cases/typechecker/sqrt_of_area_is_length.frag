#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<area> a = 4.0 * meter * meter;
  float<length> s = sqrt(a);
  c = vec4(s);
}
