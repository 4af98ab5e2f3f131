#version 330 core
#error this shader needs a light model
void main() {}
