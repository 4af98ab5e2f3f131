#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  float<1> deg = 30.0;
  c = vec4(sin(deg));
}
