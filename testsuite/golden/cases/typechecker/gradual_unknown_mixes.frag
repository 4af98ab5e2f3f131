#version 330 core
#include <safegi/prelude.sgl>
uniform float g;
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  float plain = 3.0;
  float<length> e = d * plain;
  c = vec4(e);
}
