#version 330 core
#include <safegi/prelude.sgl>
out spectrum<radiance> L;
void main() { L = spectrum<radiance>(0.0); gl_Position = vec4(0.0); }
