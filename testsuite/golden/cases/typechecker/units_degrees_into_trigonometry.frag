#version 330 core
#include <safegi/prelude.sgl>
uniform float<angle in degree> fovDeg;
out vec4 color;
void main() {
  float ok = tan(0.5 * (fovDeg in radian));
  float focal = 1.0 / tan(0.5 * fovDeg);
  color = vec4(vec3(focal * ok), 1.0);
}
