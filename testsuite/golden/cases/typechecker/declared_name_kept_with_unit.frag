#version 330 core
#include <safegi/prelude.sgl>
// The declaration's name is kept in messages: inv_length, not the first
// declared name of 1/length (pdf_length), also when a unit is given, and
// through a product or quotient by a plain number.
uniform float<inv_length in kilometer^-1> extinctionPerKm;
uniform float<length> d;
out vec4 c;
void main() {
  float<1> opticalDepth = extinctionPerKm;
  float<1> halfDepth = 0.5 * extinctionPerKm;
  c = vec4(opticalDepth * d);
}
