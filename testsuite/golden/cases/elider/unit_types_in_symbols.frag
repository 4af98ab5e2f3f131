// SYMBOLS
#version 330 core
#include <safegi/prelude.sgl>
// A uniform measured in a unit records its unit factors: a typed host value
// in reference units does not bind to it.
uniform float<length in centimeter> radiusCm;
uniform float<length in meter> radiusM;   // meter is the reference unit: just a length
out vec4 c;
void main() { c = vec4(radiusCm in meter + radiusM); }
