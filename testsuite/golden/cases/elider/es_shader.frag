#version 300 es
#include <safegi/prelude.sgl>
precision highp float;
uniform spectrum<radiance> L;
out vec4 c;
void main() { c = vec4(L, 1.0); }
