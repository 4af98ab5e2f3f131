#version 330 core
#include "no_such_file.glsl"
void main() {}
