#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<length> a = 1.0 * meter, b = 2.0 * meter;
  float<length> m = clamp(mix(min(a, b), max(a, b), 0.5), a, b);
  c = vec4(m);
}
