#version 330 core
#include <safegi/prelude.sgl>
// A length handed over as a plain number is a count of its unit: the hint divides by it.
space world;
uniform point<world> clipPoint;
uniform normal<world> clipNormal;
in point<world> P;
out vec4 c;
void main() {
  float<1> side = float<1>(dot(clipNormal, P - clipPoint));
  float<1> metres = dot(clipNormal, P - clipPoint) / meter;
  c = vec4(side, metres, 0.0, 1.0);
}
