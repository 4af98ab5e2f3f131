#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
uniform map<object, world> N;
uniform bool useN;
in vector<object> v;
in vector<object> w;
out vec3 o;
void main() {
  vector<world> a = transform(useN ? N : M, v + w);
  o = a;
  gl_Position = vec4(o, 1.0);
}
