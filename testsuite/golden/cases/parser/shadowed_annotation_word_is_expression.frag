#version 330 core
out vec4 c;
void main() {
  float point = 1.0, a = 0.5, b = 0.25;
  bool r = point < a > b;
  c = vec4(r ? 1.0 : 0.0);
}
