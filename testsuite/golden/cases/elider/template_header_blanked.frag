#version 330 core
#include <safegi/prelude.sgl>
template<dimension D,
         space S>
vector<S, D> scaled(vector<S> v, float<D> s) { return v * s / float<length>(1.0); }
space world;
uniform vector<world> v;
out vec4 c;
void main() { c = vec4(scaled(v, 2.0 * second), 1.0); }
