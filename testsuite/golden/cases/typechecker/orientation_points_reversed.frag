#version 330 core
#include <safegi/prelude.sgl>
// The vector toward the light, with the points the wrong way round: both orders
// are vector<world>, but only lightPos - P points away from the shaded point.
space world;
uniform point<world> lightPos;
in point<world, shaded> P;
out vec4 c;
void main() {
  vector<world, away> toLight = P - lightPos;
  c = vec4(toLight, 1.0);
}
