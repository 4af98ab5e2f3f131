#version 330 core
#include <safegi/prelude.sgl>
space world; space camera; space ndc;
// A triangle in normalized device coordinates carrying emitted radiance.
in point<ndc> position;
in spectrum<radiance> vertexLe;
out spectrum<radiance> Lv;
void main() {
  Lv = vertexLe;
  gl_Position = vec4(position, 1.0);
}
