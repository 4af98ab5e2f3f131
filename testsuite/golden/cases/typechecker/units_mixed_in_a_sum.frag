#version 330 core
#include <safegi/prelude.sgl>
// The scene gives the light's radius in centimetres; the bias is in metres.
uniform float<length in centimeter> radiusCm;
out vec4 color;
void main() {
  float<length> bias = 0.01 * meter;
  float<length> reach = radiusCm + bias;
  color = vec4(vec3(reach / meter), 1.0);
}
