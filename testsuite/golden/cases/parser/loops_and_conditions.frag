#version 330 core
out vec4 c;
void main() {
  float s = 0.0;
  for (int i = 0; i < 4; ++i) { if (i == 2) continue; s += float(i); }
  int j = 0;
  while (j < 3) j++;
  do { s *= 0.5; } while (s > 1.0);
  c = vec4(s);
}
