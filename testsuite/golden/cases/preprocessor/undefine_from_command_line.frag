// ARGS: -D FOO -U FOO
#version 330 core
out vec4 c;
void main() {
#ifdef FOO
  c = vec4(2.0);
#else
  c = vec4(1.0);
#endif
}
