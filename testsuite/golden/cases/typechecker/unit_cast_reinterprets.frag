#version 330 core
#include <safegi/prelude.sgl>
uniform float<length> radius;
out vec4 color;
void main() {
  float<length in centimeter> fromNumber = float<length in centimeter>(5.0);  // a number takes the unit it is given
  float<length in centimeter> cm = float<length in centimeter>(radius);
  color = vec4(vec3(float(cm + fromNumber)), 1.0);
}
