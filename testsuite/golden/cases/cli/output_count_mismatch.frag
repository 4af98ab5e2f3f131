// RAW
// ARGS: -o a.glsl -o b.glsl
#version 330 core
void main() {}
