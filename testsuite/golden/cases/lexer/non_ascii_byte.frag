#version 330 core
out vec4 c;
void main() { float Ã© = 1.0; c = vec4(1.0); }
