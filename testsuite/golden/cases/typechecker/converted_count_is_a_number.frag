#version 330 core
#include <safegi/prelude.sgl>
// float(n) of an integer is a plain number: 1 / (n · area) is a pdf per area,
// not the pdf per solid angle the MIS weight needs.
uniform int lightCount;
uniform uint sampleBits;
uniform float<area> lightArea;
uniform float<pdf_solid_angle> pdfBsdf;
out vec4 c;
void main() {
  float<pdf_area> pdfArea = 1.0 / (float(lightCount) * lightArea);
  float<1> u = float(sampleBits) * 2.3283064365386963e-10;
  float<1> weight = pdfBsdf / (pdfBsdf + 1.0 / (float(lightCount) * lightArea));
  c = vec4(pdfArea, u, weight, 1.0);
}
