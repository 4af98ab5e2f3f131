#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float meter = 2.0;
  c = vec4(meter);
}
