#version 330 core
template<dimension D>
uniform float x;
void main() {}
