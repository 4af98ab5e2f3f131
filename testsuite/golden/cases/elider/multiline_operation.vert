#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
in point<object> p;
void main() {
  point<world> q = transform(M,
                             p);
  gl_Position = vec4(q, 1.0);
}
