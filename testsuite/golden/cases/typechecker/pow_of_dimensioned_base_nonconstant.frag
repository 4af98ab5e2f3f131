#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  float e = 2.5;
  c = vec4(pow(d, 2.5));
}
