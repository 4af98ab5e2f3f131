#version 330 core
#ifdef FOO
out vec4 c;
void main() {}
