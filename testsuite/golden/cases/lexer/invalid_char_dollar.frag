#version 330 core
out vec4 c;
void main() { float $x = 1.0; c = vec4($x); }
