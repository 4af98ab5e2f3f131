#version 330 core
out vec4 c;
void main() { vec3 v = vec3(1.0); c = v; }
