#version 330 core
#include <safegi/prelude.sgl>
uniform float g;
out vec4 c;
void main() {
  g = 2.0;
  c = vec4(g);
}
