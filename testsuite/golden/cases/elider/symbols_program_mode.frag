// WITH: elider/inputs/program.vert
// SYMBOLS
#version 330 core
#include <safegi/prelude.sgl>
space world;
in normal<world> N;
out vec4 c;
void main() { c = vec4(normalize(N), 1.0); }
