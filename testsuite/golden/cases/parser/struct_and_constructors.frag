#version 330 core
struct Light { vec3 p; float r; };
out vec4 c;
void main() {
  Light l = Light(vec3(1.0), 2.0);
  float a[3] = float[3](1.0, 2.0, 3.0);
  c = vec4(l.p * l.r * float(a.length()), a[2]);
}
