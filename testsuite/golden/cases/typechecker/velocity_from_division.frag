#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<velocity> v = 3.0 * meter / (2.0 * second);
  float<length> d = v * (4.0 * second);
  c = vec4(d);
}
