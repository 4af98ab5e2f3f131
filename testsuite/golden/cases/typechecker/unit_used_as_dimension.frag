#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<meter> d = 0.0;
  c = vec4(d);
}
