#version 330 core
space ;
void main() {}
