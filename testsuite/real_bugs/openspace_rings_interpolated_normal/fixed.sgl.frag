#version 330 core
#include <safegi/prelude.sgl>
// An astronomy visualisation's planetary-ring pass (the geometry pass that
// feeds the ring shadows): fragments where the ring plane is seen edge-on,
// its normal perpendicular to the view axis, are discarded, as are those
// outside the ring's radius or where the ring texture is transparent.
space view;

in vec2 vs_st;
in float vs_screenSpaceDepth;
in normal<view> vs_normal;

uniform sampler1D ringTexture;
uniform vec2 textureOffset;

out vec4 fragColor;

void main() {
  vec2 st = (vs_st - vec2(0.5)) * 2.0;
  float radius = length(st);

  const direction<view> viewAxis = direction<view>(0.0, 0.0, 1.0);
  if (abs(dot(normalize(vs_normal), viewAxis)) <= 1.0e-3) {
    discard;
  }
  if (radius > 1.0) {
    discard;
  }
  float texCoord = (radius - textureOffset.x) / (textureOffset.y - textureOffset.x);
  if (texCoord < 0.0 || texCoord > 1.0) {
    discard;
  }
  float diffuse = length(texture(ringTexture, texCoord).rgb);
  fragColor = vec4(vec3(vs_screenSpaceDepth), 1.0);
  gl_FragDepth = (diffuse < 0.5) ? 1.0 : vs_screenSpaceDepth;
}
