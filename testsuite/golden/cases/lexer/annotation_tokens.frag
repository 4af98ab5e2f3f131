#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() { float<length/time> v = 2.0 * meter / second; c = vec4(v); }
