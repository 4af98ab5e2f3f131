#version 330 core
#include <safegi/prelude.sgl>
// -p is origin - p: in view space the vector from the shaded point to the eye.
space view;
in point<view, shaded> P;
in normal<view> N;
out vec4 c;
void main() {
  direction<view, away> V = normalize(-P);
  vector<view, toward> wrong = -P;
  c = vec4(V, dot(normalize(N), V));
}
