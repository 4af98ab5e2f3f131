#version 330 core
#include <safegi/prelude.sgl>
// A world position from the depth buffer: NDC through the inverse projection
// is a homogeneous view-space point; the whole vec4 divided by its w is the
// point with w = 1, which the view-to-world map carries. Dividing only xyz
// leaves w, and the map's translation would be scaled by it.
space clip;
space view;
space world;
uniform projmap<clip, view> viewFromClip;
uniform rigidmap<view, world> worldFromView;
uniform sampler2D<float<1>> depthTexture;
in vec2 uv;
out vec4 c;
void main() {
    vec3 ndc = vec3(uv * 2.0 - 1.0, texture(depthTexture, uv).x * 2.0 - 1.0);
    vec4 h = viewFromClip * vec4(ndc, 1.0);
    h /= h.w;
    point<world> p = (worldFromView * h).xyz;
    vec4 g = viewFromClip * vec4(ndc, 1.0);
    g.xyz /= g.w;
    point<world> q = (worldFromView * g).xyz;
    c = vec4(p + (q - p), 1.0);
}
