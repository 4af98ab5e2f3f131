// ARGS: -D GAIN=2.0 -D USE_GAIN
#version 330 core
out vec4 c;
void main() {
#ifdef USE_GAIN
  c = vec4(GAIN);
#else
  c = vec4(1.0);
#endif
}
