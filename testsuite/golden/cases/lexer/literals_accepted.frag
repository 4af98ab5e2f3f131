#version 400 core
out vec4 c;
void main() {
  int a = 0x1F + 017 + 42;
  uint b = 0xFFFFFFFFu + 3u;
  float f = .5e-3 + 1.5f + 2e3 + 1.;
  double d = 1.0lf + 2.5LF;
  c = vec4(float(a) + float(b) + f + float(d));
}
