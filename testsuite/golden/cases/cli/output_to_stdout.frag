// RAW
// ARGS: -o -
#version 330 core
#include <safegi/prelude.sgl>
uniform float<length> d;
out vec4 c;
void main() { c = vec4(d); }
