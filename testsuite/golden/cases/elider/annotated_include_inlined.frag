#version 330 core
#include <safegi/prelude.sgl>
#include "inputs/lights.sgl"
out vec4 c;
void main() { c = vec4(attenuate(Le, 2.0 * meter), 1.0); }
