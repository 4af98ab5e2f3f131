#version 420 core
out vec4 c;
#define GREY \
  vec4(0.5)
void main() { c = GREY; }
