#version 330 core
#include <safegi/prelude.sgl>
// reflect() takes GLSL's incident direction, which points toward the surface;
// an outgoing direction (away from it) must be negated first.
space world;
uniform point<world> eyePos;
uniform normal<world> n;
in point<world, shaded> P;
out vec4 c;
void main() {
  direction<world, away> wo = normalize(eyePos - P);
  direction<world, away> wi = reflect(wo, n);
  c = vec4(wi, 1.0);
}
