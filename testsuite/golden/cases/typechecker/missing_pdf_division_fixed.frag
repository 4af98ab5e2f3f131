#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<brdf> f;
uniform spectrum<radiance> Li;
uniform float<proj> cosT;
uniform float<pdf_solid_angle> pdf;
out vec4 c;
void main() {
  spectrum<radiance> L = f * Li * cosT / pdf;
  c = vec4(L, 1.0);
}
