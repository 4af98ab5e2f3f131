#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
space eye;
uniform map<object, world> M;
uniform map<world, eye> V;
in point<object> p;
void main() {
  map<object, eye> a = V * M;
  map<object, eye> b = compose(V, M);
  point<eye> q = a * p + (b * p - a * p);
  gl_Position = vec4(q, 1.0);
}
