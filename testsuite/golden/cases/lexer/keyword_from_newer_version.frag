#version 330 core
out vec4 c;
void main() { int sample = 1; c = vec4(sample); }
