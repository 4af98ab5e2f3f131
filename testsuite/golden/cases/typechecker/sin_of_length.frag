#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  c = vec4(sin(d));
}
