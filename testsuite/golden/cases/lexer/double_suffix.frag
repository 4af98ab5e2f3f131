#version 400 core
out vec4 c;
void main() { double d = 1.0lf; c = vec4(float(d)); }
