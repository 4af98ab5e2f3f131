// ARGS: -I preprocessor/inputs
#version 330 core
#include "common.glsl"
out vec4 c;
void main() { c = vec4(twice(1.0)); }
