#version 330 core
#include <safegi/prelude.sgl>
spectrum<radiance> shade(spectrum<brdf> f, spectrum<radiance> Li, float<proj> cosT, float<pdf_projected_solid_angle> pdf) {
  return f * Li / pdf;
}
uniform spectrum<brdf> f;
uniform spectrum<radiance> Li;
out vec4 c;
void main() { c = vec4(shade(f, Li, float<proj>(1.0), float<pdf_projected_solid_angle>(1.0)), 1.0); }
