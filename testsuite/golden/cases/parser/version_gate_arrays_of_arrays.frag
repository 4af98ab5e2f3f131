#version 330 core
out vec4 color;
uniform float weights[2][3];
void main() { color = vec4(weights[1][2]); }
