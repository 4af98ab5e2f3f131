#version 330 core
#include <safegi/prelude.sgl>
space world;
struct Hit { point<world> p; normal<world> n; float<length> t; };
uniform point<world> o;
out vec4 c;
void main() { Hit h = Hit(o, normal<world>(vec3(0.0, 0.0, 1.0)), 0.0); c = vec4(h.p + h.n * h.t, dot(h.n, h.n)); }
