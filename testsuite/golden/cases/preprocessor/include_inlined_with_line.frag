#version 330 core
#include "inputs/common.glsl"
out vec4 c;
void main() { c = vec4(twice(0.25)); }
