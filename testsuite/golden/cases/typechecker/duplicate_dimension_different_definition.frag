#version 330 core
dimension length;
dimension area = length^2;
dimension area = length^3;
void main() {}
