#version 330 core
dimension length;
dimension root_length = length^0.5;
void main() {}
