#version 330 core
dimension length;
dimension length;
space world;
space world;
out vec4 c;
void main() { c = vec4(1.0); }
