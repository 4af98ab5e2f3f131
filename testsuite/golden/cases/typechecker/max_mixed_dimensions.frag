#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> a = 1.0 * meter;
  float<time> t = 1.0 * second;
  c = vec4(max(a, t));
}
