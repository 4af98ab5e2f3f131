#version 330 core
#include <safegi/prelude.sgl>
// The declaration's name is kept in messages: inv_length, not the first
// declared name of 1/length (pdf_length), also when a unit is given.
uniform float<inv_length in kilometer^-1> extinctionPerKm;
uniform float<length> d;
out vec4 c;
void main() {
  float<1> opticalDepth = extinctionPerKm;
  c = vec4(opticalDepth * d);
}
