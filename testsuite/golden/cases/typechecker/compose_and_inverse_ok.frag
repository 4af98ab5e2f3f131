#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
space eye;
uniform map<object, world> M;
uniform map<world, eye> V;
uniform point<object> p;
out vec4 c;
void main() {
  map<object, eye> m = V * M;
  map<world, object> back = inverse(M);
  point<object> q = back * (inverse(V) * (m * p));
  c = vec4(q, 1.0);
}
