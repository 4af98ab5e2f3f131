// ARGS: --target-env vulkan1.2
// Nothing narrows implicitly: a float is not a float16_t, an int not a uint8_t, an int64_t not an int.
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
layout(location = 0) out vec4 o;
void main() {
  float16_t h = 1.0;
  uint8_t c = 1;
  int64_t a = 1l;
  int b = a;
  o = vec4(h, c, a, b);
}
