#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 1.0;
  c = vec4(d);
}
