#version 330 core
#include <safegi/prelude.sgl>
// 'in' binds tighter than '*': only the right-hand factor is converted.
uniform float<length in centimeter> radiusCm;
out vec4 color;
void main() {
  float<area> disk = 3.14159 * radiusCm * radiusCm in (meter^2);
  color = vec4(vec3(disk / (meter * meter)), 1.0);
}
