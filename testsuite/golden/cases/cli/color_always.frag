// ARGS: --color=always
#version 330 core
void main() { x = 1; }
