#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<pdf_solid_angle> pdf = float<pdf_solid_angle>(0.5);
  c = pdf > 0.0 ? vec4(1.0) : vec4(0.0);
}
