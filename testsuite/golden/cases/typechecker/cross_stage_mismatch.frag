// WITH: typechecker/inputs/stage.vert
#version 330 core
#include <safegi/prelude.sgl>
in spectrum<irradiance> L;
out vec4 c;
void main() { c = vec4(L, 1.0); }
