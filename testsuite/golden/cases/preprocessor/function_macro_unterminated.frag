#version 330 core
#define SQ(x) ((x) * (x))
out vec4 c;
void main() { c = vec4(SQ(1.0); }
