#version 330 core
uniform Camera { mat4 view; }
void main() {}
