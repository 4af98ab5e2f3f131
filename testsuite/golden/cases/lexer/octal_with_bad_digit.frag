#version 330 core
out vec4 c;
void main() { int i = 09; c = vec4(i); }
