#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
space light_s;
uniform map<object, world> M;
uniform point<light_s> p;
out vec4 c;
void main() {
  point<world> q = M * p;
  c = vec4(q, 1.0);
}
