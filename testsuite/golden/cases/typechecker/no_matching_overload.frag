#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  c = vec4(cross(vec2(1.0), vec2(0.0)), 1.0);
}
