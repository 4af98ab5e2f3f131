#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
template<space S>
float<length> dist(point<S> p, point<S> q) { return length(p - q); }
uniform point<world> a;
uniform point<object> b;
out vec4 c;
void main() {
  c = vec4(dist(a, b));
}
