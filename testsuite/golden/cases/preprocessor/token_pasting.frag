#version 330 core
#define CAT(a, b) a##b
out vec4 c;
void main() { float xy = 1.0; c = vec4(CAT(x, y)); }
