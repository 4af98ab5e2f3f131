#version 330 core
out vec4 c;
void main() { float goto = 1.0; c = vec4(goto); }
