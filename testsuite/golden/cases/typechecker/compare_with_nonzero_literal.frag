#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  c = d > 1.0 ? vec4(1.0) : vec4(0.0);
}
