#version 330 core
#include <safegi/prelude.sgl>
// A shader pack's temporal ambient-occlusion pass accumulates the bent normal
// over frames. The history stores last frame's bent normal in last frame's
// view space; before it is blended with this frame's (current view space) it
// is carried back to world space by last frame's view rotation (v * m: its
// transpose, the inverse of a rotation) and forward by this frame's.
space world;
space view;
space prev_view;

uniform rigidmap<world, view> gbufferModelView;
uniform rigidmap<world, prev_view> gbufferPreviousModelView;
uniform sampler2D historyTex;        // .zw: octahedral-free xy of the bent normal

in vec2 uv;
in direction<view> currentBentNormal;
out vec4 historyOut;

void main() {
    vec4 history = texture(historyTex, uv);
    vec3 decoded;
    decoded.xy = history.zw * 2.0 - 1.0;
    decoded.z = sqrt(clamp(1.0 - dot(decoded.xy, decoded.xy), 0.0, 1.0));
    direction<prev_view> historyPrev = direction<prev_view>(decoded);

    direction<view> historyBentNormal = mat3(gbufferModelView) * (historyPrev * mat3(gbufferPreviousModelView));

    vec3 bentNormal = normalize(mix(historyBentNormal, currentBentNormal, 0.1));
    historyOut = vec4(history.xy, bentNormal.xy * 0.5 + 0.5);
}
