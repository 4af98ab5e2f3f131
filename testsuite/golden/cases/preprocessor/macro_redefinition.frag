#version 330 core
#define N 1
#define N 2
void main() {}
