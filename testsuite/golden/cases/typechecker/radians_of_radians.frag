#version 330 core
#include <safegi/prelude.sgl>
// An angle already in radians given to radians() would be scaled by π/180 again.
uniform float<angle> outerCone;
out vec4 c;
void main() {
  float<angle> outer = radians(outerCone);
  c = vec4(float(outer));
}
