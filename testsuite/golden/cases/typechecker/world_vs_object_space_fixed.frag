#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
uniform map<object, world> M;
uniform point<world> pw;
uniform point<object> po;
out vec4 c;
void main() {
  vector<world> v = pw - M * po;
  c = vec4(v, 1.0);
}
