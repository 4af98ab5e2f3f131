#version 330 core
#include <safegi/prelude.sgl>
// A cosine scaling a unit vector is a component along it, not a projected
// area: the reflection written out and Gram-Schmidt need no casts, also
// when the unit vector was scaled by a plain number first (2.0 * n).
space world;
uniform normal<world> n;
uniform direction<world> wo;
uniform direction<world> tangentIn;
out vec4 c;
void main() {
  direction<world> r = normalize(2.0 * dot(n, wo) * n - wo);
  direction<world> rScaledFirst = normalize(2.0 * n * dot(n, wo) - wo);
  direction<world> t = normalize(tangentIn - dot(tangentIn, n) * n);
  c = vec4(r + rScaledFirst + t, 1.0);
}
