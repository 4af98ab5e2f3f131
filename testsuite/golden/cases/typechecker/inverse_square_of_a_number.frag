#version 330 core
#include <safegi/prelude.sgl>
// inverse_square takes a length.
uniform float<area> a;
out vec4 c;
void main() {
  c = vec4(inverse_square(a));
}
