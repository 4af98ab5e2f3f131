#version 330 core
#else
void main() {}
