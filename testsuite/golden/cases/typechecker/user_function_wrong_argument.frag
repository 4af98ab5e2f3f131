#version 330 core
#include <safegi/prelude.sgl>
float<area> sq(float<length> x) { return x * x; }
out vec4 c;
void main() { c = vec4(sq(2.0 * second)); }
