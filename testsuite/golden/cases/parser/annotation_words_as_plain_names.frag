#version 330 core
out vec4 c;
struct point { float x; };
float map(float v) { return v * 2.0; }
void main() {
  float normal = 1.0;
  float vector = 2.0, direction = 3.0, spectrum = 4.0;
  point p = point(normal);
  c = vec4(map(p.x) + vector + direction + spectrum);
}
