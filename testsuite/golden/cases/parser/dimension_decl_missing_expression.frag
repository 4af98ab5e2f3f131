#version 330 core
dimension length;
dimension area = ;
void main() {}
