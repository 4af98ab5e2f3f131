#version 330 core
#include <safegi/prelude.sgl>
// The declaration's name is kept in messages: inv_length, not the first
// declared name of 1/length (pdf_length), also when a unit is given, and
// through a product or quotient by a plain number and a built-in such as max.
uniform float<inv_length in kilometer^-1> extinctionPerKm;
uniform float<length> d;
out vec4 c;
void main() {
  float<1> opticalDepth = extinctionPerKm;
  float<1> halfDepth = 0.5 * extinctionPerKm;
  float<1> nonNegative = max(extinctionPerKm, 0.0);
  c = vec4(opticalDepth * d);
}
