#version 330 core
#include <safegi/prelude.sgl>
// A spot light: the direction to the light is a difference of points.
space world;
uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
in point<world> P;
in normal<world> N;
out vec4 color;
void main() {
  direction<world> wi = normalize(lightPos);
  float<proj> cosTheta = max(dot(normalize(N), wi), 0.0);
  color = vec4(lightI * float(cosTheta), 1.0);
}
