#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<time> t = 2.0 * second;
  c = vec4(exp(t));
}
