#version 330 core
#include <safegi/prelude.sgl>
// A normal in an input block is interpolated too, unless the member is flat.
space world;
uniform direction<world> l;
in VS { normal<world> n; flat normal<world> f; } vs;
out vec4 c;
void main() { c = vec4(max(dot(vs.n, l), 0.0) + max(dot(vs.f, l), 0.0)); }
