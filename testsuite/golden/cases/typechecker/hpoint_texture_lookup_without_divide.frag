#version 330 core
#include <safegi/prelude.sgl>
// Screen-space reflections sample the previous frame where the reflected point projects.
space world;
space clip;
uniform projmap<world, clip> clipFromWorld;
uniform sampler2D<spectrum<radiance>> previousFrame;
in point<world> hitPoint;
out vec4 color;
void main() {
  hpoint<clip> h = clipFromWorld * hitPoint;
  vec2 uv = h.xy * 0.5 + 0.5;
  spectrum<radiance> L = spectrum<radiance>(texture(previousFrame, uv).rgb);
  color = vec4(L, 1.0);
}
