#version 330 core
#include <safegi/prelude.sgl>
uniform float<length> depths[4];
uniform spectrum<radiance>[2] colors;
out vec4 c;
void main() { c = vec4(colors[0] * depths[1] + colors[1] * depths[3], 1.0); }
