// ARGS: --strict
#version 330 core
#include <safegi/prelude.sgl>
uniform float g;
out vec4 c;
void main() {
  c = vec4(g);
}
