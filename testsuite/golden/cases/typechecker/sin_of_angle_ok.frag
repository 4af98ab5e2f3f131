#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<angle> a = 30.0 * degree;
  float<1> s = sin(a);
  float<angle> back = asin(s);
  c = vec4(s, back, radians(45.0), 1.0);
}
