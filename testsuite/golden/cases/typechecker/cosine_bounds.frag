#version 330 core
#include <safegi/prelude.sgl>
// A cosine kept off zero or clamped to [0, 1] stays a cosine: the literal bounds of min,
// max and clamp take its dimension, a length's guard too (max(d, 1e-4) keeps a
// division finite); added to a length, a literal still needs its unit.
space world;
uniform normal<world> N;
uniform direction<world> L;
uniform spectrum<radiance> Li;
uniform spectrum<brdf> f;
uniform float<length> d;
out vec4 c;
void main() {
  float<proj> clamped = clamp(dot(N, L), 0.001, 1.0);
  float<proj> floored = max(dot(N, L), 1e-4);
  float<1> saturated = clamp(dot(N, L), 0.0, 1.0);
  spectrum<radiance> Lo = f * Li * clamped * saturated * float<solid_angle>(1.0);
  float<length> reach = max(d, 1e-4);
  float<length> padded = d + 1e-4;
  c = vec4(Lo * floored, reach + padded);
}
