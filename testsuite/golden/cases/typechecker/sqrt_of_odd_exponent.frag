#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 4.0 * meter;
  c = vec4(sqrt(d));
}
