#version 330 core
#include <safegi/prelude.sgl>
uniform point<wrold> p;
out vec4 c;
void main() {
  c = vec4(p, 1.0);
}
