#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform normal<world> n;
uniform direction<world> wi;
uniform spectrum<radiance> Li;
uniform float<solid_angle> dw;
out vec4 c;
void main() {
  float<proj> cosT = max(dot(n, wi), 0.0);
  spectrum<irradiance> E = Li * dw;
  c = vec4(E, 1.0);
}
