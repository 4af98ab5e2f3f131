out vec4 c;
#version 330 core
void main() { c = vec4(1.0); }
