#version 330 core
out vec4 c;
void main() { uint u = 4294967296u; c = vec4(u); }
