#version 330 core
#include <safegi/prelude.sgl>
space world;
space clip;
uniform projmap<world, clip> clipFromWorld;
uniform sampler2D<float<1>> depth;
uniform sampler2DShadow shadow;
in point<world> P;
out vec4 color;
void main() {
  hpoint<clip> h = clipFromWorld * P;
  vec2 uv = h.xy / h.w * 0.5 + 0.5;       // divided: plain coordinates
  float invW = 1.0 / h.w;
  vec2 uv2 = h.xy * invW * 0.5 + 0.5;     // the same, by the reciprocal
  float<1> a = texture(depth, uv).r + texture(depth, uv2).r;
  float b = textureProj(shadow, vec4(h.xy * 0.5 + 0.5 * h.w, h.z * 0.5 + 0.5 * h.w, h.w));  // textureProj divides
  color = vec4(vec3(a * b), 1.0);
}
