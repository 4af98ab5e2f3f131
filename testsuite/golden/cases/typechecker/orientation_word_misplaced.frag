#version 330 core
#include <safegi/prelude.sgl>
// Only vectors and directions point away or toward; only a point is shaded.
space world;
in point<world, away> P;
out vec4 c;
void main() { c = vec4(P, 1.0); }
