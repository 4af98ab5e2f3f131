#version 400 core
layout(triangles) in;
void main() { gl_Position = gl_in[0].gl_Position * gl_TessCoord.x; }
