#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<brdf> f;
uniform spectrum<radiance> Le;
uniform float<proj> cosT;
uniform float<pdf_area> pdfA;
out vec4 c;
void main() {
  spectrum<radiance> L = f * Le * cosT / pdfA;
  c = vec4(L, 1.0);
}
