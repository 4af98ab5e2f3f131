#version 330 core
#include <safegi/prelude.sgl>
// Sums and differences of vec4(x, w)s keep what they carry while w comes out right for the
// kind (1 for a point, 0 for a vector); a vector left with w = 1 is told.
space view;
uniform point<view> lightPos;
in point<view> P;
in vector<view> offset;
out vector<view> toLight;
out point<view> moved;
void main() {
  toLight = (vec4(lightPos, 1.0) - vec4(P, 1.0)).xyz;
  moved = (vec4(P, 1.0) + vec4(offset, 0.0)).xyz;
  vec4 stray = vec4(lightPos, 1.0) - vec4(P, 0.0);
  gl_Position = vec4(P, 1.0);
}
