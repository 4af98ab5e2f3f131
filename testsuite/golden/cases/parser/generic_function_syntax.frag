#version 330 core
#include <safegi/prelude.sgl>
template<dimension D, space S>
float<D> pick(float<D> a, point<S> p) { return a; }
space world;
uniform point<world> p;
out vec4 c;
void main() { float<length> d = pick(2.0 * meter, p); c = vec4(d); }
