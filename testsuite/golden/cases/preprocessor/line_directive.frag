#version 330 core
out vec4 c;
#line 100
void main() { c = vec4(1.0) @; }
