#version 330 core
#include <safegi/prelude.sgl>
// What casts are for: a change of measure moves only ratio dimensions
// (solid angle, proj), a program's own ratio base too; constants and
// unannotated values take what the cast gives them.
dimension pixel : ratio;
dimension pixel : ratio;
uniform float<pdf_area> pdfA;
uniform float<length> r;
uniform float<proj> cosLight;
uniform float<1> coverage;
uniform float raw;
out vec4 c;
void main() {
  float<pdf_solid_angle> pdfW = float<pdf_solid_angle>(pdfA * r * r / cosLight);
  float<pixel> covered = float<pixel>(coverage);
  float<length> half_ = float<length>(0.5 * 2.0);
  float<length> adopted = float<length>(raw);
  c = vec4(pdfW, covered, half_, adopted);
}
