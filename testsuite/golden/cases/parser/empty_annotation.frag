#version 330 core
#include <safegi/prelude.sgl>
uniform float<> d;
void main() {}
