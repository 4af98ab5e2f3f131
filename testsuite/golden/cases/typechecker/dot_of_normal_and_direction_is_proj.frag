#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform normal<world> n;
uniform direction<world> w;
out vec4 c;
void main() {
  float<proj> cosT = dot(n, w);
  c = vec4(cosT);
}
