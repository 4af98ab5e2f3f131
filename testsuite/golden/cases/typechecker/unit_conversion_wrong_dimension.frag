#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform float<length in centimeter> radiusCm;
uniform point<world> P;
out vec4 color;
void main() {
  float<time> t = radiusCm in second;
  vec3 q = P in centimeter;
  vec3 r = P in wrold;
  color = vec4(1.0);
}
