#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  float<area> a = d;
  c = vec4(a);
}
