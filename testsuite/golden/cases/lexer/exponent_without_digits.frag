#version 330 core
out vec4 c;
void main() { float f = 1.0e; c = vec4(f); }
