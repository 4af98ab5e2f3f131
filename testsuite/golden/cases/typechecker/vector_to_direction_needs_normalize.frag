#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform vector<world> v;
out vec4 c;
void main() {
  direction<world> d = v;
  c = vec4(d, 1.0);
}
