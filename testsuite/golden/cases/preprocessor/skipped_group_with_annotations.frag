#version 330 core
out vec4 c;
void main() {
#if 0
  float<length> d = whatever;
#endif
  c = vec4(1.0);
}
