#version 460
#include <safegi/prelude.sgl>
// A ray-traced sample's primary rays, written as a full-screen pass: the
// pixel's NDC point on the far plane is carried back to view space by the
// inverse projection, divided by its w, and its direction from the eye
// (the origin of view space) carried to world space by the camera's
// view-to-world map.
space world;
space view : eye;
space clip;

layout(binding = 0) uniform CameraProperties {
    rigidmap<view, world> viewInverse;
    projmap<clip, view> projInverse;
} cam;
uniform vec2 launchSize;

layout(location = 0) out vec4 outOrigin;
layout(location = 1) out vec4 outDirection;

void main() {
    vec2 pixelCenter = gl_FragCoord.xy;
    vec2 inUV = pixelCenter / launchSize;
    vec2 d = inUV * 2.0 - 1.0;

    vec4 origin = cam.viewInverse * vec4(0.0, 0.0, 0.0, 1.0);
    hpoint<view> target = cam.projInverse * vec4(d.x, d.y, 1.0, 1.0);
    vec4 direction = cam.viewInverse * vec4(normalize(target.xyz / target.w), 0.0);

    outOrigin = origin;
    outDirection = direction;
}
