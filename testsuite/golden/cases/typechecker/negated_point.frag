#version 330 core
#include <safegi/prelude.sgl>
// -p is origin - p: in a space whose origin is the eye, the vector from the
// shaded point to the eye. In another space it depends on where the origin is.
space view : eye;
space world;
in point<view, shaded> P;
in normal<view> N;
in point<world> Pw;
out vec4 c;
void main() {
  direction<view, away> V = normalize(-P);
  vector<view, toward> wrong = -P;
  vector<world> toOrigin = -Pw;
  c = vec4(V, dot(normalize(N), V));
}
