#version 150
#include "inputs/twice.glsl"
out vec4 c;
void main() { c = vec4(twice(1.0)); }
