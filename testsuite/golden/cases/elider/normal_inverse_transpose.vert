#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
uniform rigidmap<object, world> R;
in normal<object> n;
out vec3 o;
void main() {
  normal<world> a = M * n;   // non-rigid: inverse transpose
  normal<world> b = R * n;   // rigid: like a vector
  o = a + b;
  gl_Position = vec4(o, 1.0);
}
