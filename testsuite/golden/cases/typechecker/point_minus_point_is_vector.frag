#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform point<world> a;
uniform point<world> b;
out vec4 c;
void main() {
  vector<world> v = a - b;
  point<world> m = b + v * 0.5;
  c = vec4(m, 1.0);
}
