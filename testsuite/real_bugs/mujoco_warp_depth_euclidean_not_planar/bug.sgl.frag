#version 330 core
#include <safegi/prelude.sgl>
// A GPU physics simulator's ray-cast depth camera: each pixel's ray is traced
// to the nearest hit, and the depth image stores the planar depth (the hit's
// distance along the camera's optical axis, as a pinhole depth sensor and its
// intrinsics expect), not the distance along the ray.
space world;

uniform point<world> camPos;
uniform direction<world> camForward;
uniform direction<world> camRight;
uniform direction<world> camUp;
uniform float<1> tanHalfFovY;
uniform float<1> aspect;
uniform vec2 resolution;
uniform float<length> groundHeight;
uniform float<length> maxDepth;

out float depthOut;

float<length> hitGround(point<world> o, direction<world> d) {
    float down = -d.y;
    return down > 0.0 ? min((o.y - groundHeight) / down, maxDepth) : maxDepth;
}

void main() {
    vec2 ndc = (gl_FragCoord.xy / resolution) * 2.0 - 1.0;
    vec3 rayDir = normalize(camForward + ndc.x * tanHalfFovY * aspect * camRight + ndc.y * tanHalfFovY * camUp);
    float<length> t = hitGround(camPos, rayDir);
    float<length> depth = t;
    depthOut = depth;
}
