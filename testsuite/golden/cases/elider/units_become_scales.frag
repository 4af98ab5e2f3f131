#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> d = 3.0 * centimeter + 2.0 * kilometer;
  float<angle> a = 45.0 * degree;
  c = vec4(d, a, 0.0, 1.0);
}
