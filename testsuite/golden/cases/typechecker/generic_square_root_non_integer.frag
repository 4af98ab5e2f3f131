#version 330 core
#include <safegi/prelude.sgl>
template<dimension D>
float<D> sq(float<D * D> a) { return sqrt(a); }
out vec4 c;
void main() {
  float<length> d = 2.0 * meter;
  c = vec4(sq(d));
}
