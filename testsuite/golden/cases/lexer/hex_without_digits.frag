#version 330 core
out vec4 c;
void main() { int i = 0x; c = vec4(i); }
