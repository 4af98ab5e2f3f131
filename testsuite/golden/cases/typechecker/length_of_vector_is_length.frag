#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform vector<world> v;
out vec4 c;
void main() {
  float<length> d = length(v);
  c = vec4(d);
}
