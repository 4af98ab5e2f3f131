#version 330 core
#include <safegi/prelude.sgl>
space world;
space object;
uniform rigidmap<object, world> R;
uniform normal<object> n;
out vec4 c;
void main() {
  normal<world> m = R * n;
  c = vec4(m, 1.0);
}
