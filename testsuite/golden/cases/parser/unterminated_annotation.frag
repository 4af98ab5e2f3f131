#version 330 core
#include <safegi/prelude.sgl>
uniform float<length d;
void main() {}
