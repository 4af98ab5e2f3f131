#version 330 core
#include <safegi/prelude.sgl>
float<length> f() { return 2.0 * second; }
out vec4 c;
void main() { c = vec4(f()); }
