#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
in point<object> p;
out point<world> q;
void main() {
  q = M * p;
  gl_Position = vec4(q, 1.0);
}
