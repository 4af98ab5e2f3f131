#version 330 core
#include "inputs/broken.glsl"
void main() {}
