// ARGS: -S pixel
#version 330 core
void main() {}
