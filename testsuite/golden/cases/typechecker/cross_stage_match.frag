// WITH: typechecker/inputs/stage.vert
// SYMBOLS
#version 330 core
#include <safegi/prelude.sgl>
in spectrum<radiance> L;
out vec4 c;
void main() { c = vec4(L, 1.0); }
