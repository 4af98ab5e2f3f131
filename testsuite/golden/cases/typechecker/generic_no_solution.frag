#version 330 core
#include <safegi/prelude.sgl>
template<dimension D>
float<D> lerp(float<D> a, float<D> b, float<1> t) { return a + (b - a) * t; }
out vec4 c;
void main() {
  c = vec4(lerp(1.0 * meter, 2.0 * second, 0.5));
}
