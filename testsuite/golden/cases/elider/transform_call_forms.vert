#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
in point<object> p;
in vector<object> v;
in direction<object> d;
in normal<object> n;
out vec3 o;
void main() {
  point<world> a = transform(M, p);
  vector<world> b = transform(M, v);
  direction<world> e = normalize(transform(M, d));
  normal<world> f = transform_normal(M, n);
  o = a + b;
  o = o + e + f;
  gl_Position = vec4(o, 1.0);
}
