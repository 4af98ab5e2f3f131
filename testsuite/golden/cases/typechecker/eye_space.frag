#version 330 core
#include <safegi/prelude.sgl>
// A space whose origin is the eye (space view : eye;): a point is the vector from the eye to it,
// so normalize(P) is the eye ray toward the shaded point and length(P) its distance; in
// another space a point has no length.
space view : eye;
space world;
uniform samplerCube<spectrum<radiance>, view> env;
uniform point<world> lightW;
in point<view, shaded> P;
in normal<view> N;
out vec4 c;
void main() {
  direction<view, toward> I = normalize(P);
  direction<view, away> R = reflect(I, normalize(N));
  float<length> d = length(P);
  direction<view, away> Rbad = reflect(-I, normalize(N));
  float<length> e = length(lightW);
  c = vec4(texture(env, R).rgb, d);
}
