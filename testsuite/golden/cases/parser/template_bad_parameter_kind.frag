#version 330 core
template<unit U>
float f(float x) { return x; }
void main() {}
