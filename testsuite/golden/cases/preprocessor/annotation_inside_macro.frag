#version 330 core
#include <safegi/prelude.sgl>
#define RADIANCE spectrum<radiance>
uniform RADIANCE Le;
out vec4 c;
void main() { RADIANCE L = Le * 2.0; c = vec4(L, 1.0); }
