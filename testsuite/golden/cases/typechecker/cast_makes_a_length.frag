#version 330 core
#include <safegi/prelude.sgl>
// The real bug `1.0 / distance * distance` (= 1) cast to the inverse-square law:
// a cast may change ratio dimensions only, and this one would add length⁻².
space world;
uniform point<world> lightPos;
uniform spectrum<intensity> I;
in point<world> P;
out vec4 c;
void main() {
  float<length> d = distance(lightPos, P);
  float<solid_angle_per_projected_area> g = float<solid_angle_per_projected_area>(1.0 / d * d);
  c = vec4(I * g, 1.0);
}
