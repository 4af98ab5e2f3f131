#version 330 core
#include <safegi/prelude.sgl>
// Fog by view distance: the eye is the origin of view space, and saying so is explicit.
space view;
uniform float<inv_length> density;
in point<view> P;
out vec4 color;
void main() {
  float<length> dist = length(P);
  float<length> fine = length(vector<view>(P));
  color = vec4(vec3(exp(-density * fine)), 1.0);
}
