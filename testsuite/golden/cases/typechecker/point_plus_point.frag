#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform point<world> a;
uniform point<world> b;
out vec4 c;
void main() {
  c = vec4(a + b, 1.0);
}
