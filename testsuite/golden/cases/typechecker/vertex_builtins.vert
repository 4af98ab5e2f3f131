#version 330 core
in vec3 p;
void main() { gl_Position = vec4(p, 1.0); gl_PointSize = 2.0; }
