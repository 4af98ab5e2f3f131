#version 330 core
#include <safegi/prelude.sgl>
// inverse_square(d): the inverse-square law of a length, checked, erased to
// 1.0 / (d * d) (a helper for an argument that is not a variable).
space world;
uniform point<world> lightPos;
uniform spectrum<intensity> I;
uniform float<length> offset;
in point<world> P;
in normal<world> N;
out vec4 c;
void main() {
  float<length> d = distance(lightPos, P);
  float<proj> cosTheta = max(dot(normalize(N), normalize(lightPos - P)), 0.0);
  spectrum<irradiance> E = I * inverse_square(d) * cosTheta;
  spectrum<irradiance> E2 = I * inverse_square(d + offset) * cosTheta;
  c = vec4(E + E2, 1.0);
}
