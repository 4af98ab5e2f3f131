#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
space clip;
space eye;
uniform map<object, world> M;
uniform map<eye, clip> P;
out vec4 c;
void main() {
  map<object, clip> m = P * M;
  c = vec4(m[0]);
}
