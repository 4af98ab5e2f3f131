#version 330 core
precision mediump float;
flat in int id;
noperspective in vec2 uv;
layout(location = 0) out vec4 c;
void main() { c = vec4(uv, float(id), 1.0); }
