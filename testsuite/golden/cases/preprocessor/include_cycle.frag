#version 330 core
#include "inputs/cycle_a.glsl"
void main() {}
