#version 330 core
#include <safegi/prelude.sgl>
#include "inputs/spaces.sgl"
uniform point<world> p;
out vec4 c;
void main() { c = vec4(p, 1.0); }
