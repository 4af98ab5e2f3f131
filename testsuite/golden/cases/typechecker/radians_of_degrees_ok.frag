#version 330 core
#include <safegi/prelude.sgl>
// radians() takes an angle measured in degrees (or a plain number of degrees)
// and gives the angle; degrees() gives an angle in degrees.
uniform float<angle in degree> innerConeDeg;
uniform float<angle> outerCone;
out vec4 c;
void main() {
  float<angle> inner = radians(innerConeDeg);
  float<angle> fixedCone = radians(45.0);
  float<angle in degree> outerDeg = degrees(outerCone);
  float cosInner = cos(radians(innerConeDeg));
  c = vec4(cosInner, cos(fixedCone), float(outerDeg), float(inner));
}
