// ARGS: --target-env vulkan1.2
// Without an extension that declares them, the explicit arithmetic types are names, and the help says which.
#version 450
layout(location = 0) out vec4 o;
void main() {
  float16_t h = float16_t(1.0);
  i64vec2 v;
  o = vec4(h);
}
