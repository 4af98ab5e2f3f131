#version 330 core
#include <safegi/prelude.sgl>
// A cosine scaling a unit vector is a component along it, not a projected
// area: the reflection written out and Gram-Schmidt need no casts.
space world;
uniform normal<world> n;
uniform direction<world> wo;
uniform direction<world> tangentIn;
out vec4 c;
void main() {
  direction<world> r = normalize(2.0 * dot(n, wo) * n - wo);
  direction<world> t = normalize(tangentIn - dot(tangentIn, n) * n);
  c = vec4(r + t, 1.0);
}
