#version 330 core
#include <safegi/prelude.sgl>
// A plain number where the cosine is expected is still the missing cosine.
space world;
uniform normal<world> n;
uniform direction<world> wi;
uniform spectrum<radiance> Li;
uniform spectrum<brdf> Kd;
out vec4 c;
void main() {
  float<1> wrap = (float<1>(dot(n, wi)) + 0.5) / 1.5;
  spectrum<radiance> L = Kd * Li * wrap * float<solid_angle>(1.0);
  c = vec4(L, 1.0);
}
