#version 330 core
#include <safegi/prelude.sgl>
out vec4 c;
void main() {
  c = vec4(undefinedThing);
}
