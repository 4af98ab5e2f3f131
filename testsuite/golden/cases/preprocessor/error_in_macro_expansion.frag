#version 330 core
#include <safegi/prelude.sgl>
#define ADD_LEN(a, b) ((a) + (b))
out vec4 c;
void main() { float<length> d = 1.0 * meter; float<time> t = 1.0 * second; c = vec4(ADD_LEN(d, t)); }
