#version 330 core
dimension length;
unit meter length = 1.0;
void main() {}
