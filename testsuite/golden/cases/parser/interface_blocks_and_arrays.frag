#version 430 core
layout(std140) uniform Lights { vec4 position[4]; vec4 color[4]; } lights;
in Vertex { vec3 n; vec2 uv; } v;
out vec4 c;
void main() { float w[2][3]; w[1][2] = 1.0; c = lights.color[1] * w[1][2] * v.uv.x; }
