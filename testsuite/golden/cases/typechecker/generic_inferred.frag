#version 330 core
#include <safegi/prelude.sgl>
template<dimension D>
float<D> lerp(float<D> a, float<D> b, float<1> t) { return a + (b - a) * t; }
out vec4 c;
void main() {
  float<length> d = lerp(1.0 * meter, 2.0 * meter, 0.5);
  float<time> t = lerp(1.0 * second, 3.0 * second, 0.25);
  c = vec4(d, t, 0.0, 1.0);
}
