#version 450
#include <safegi/prelude.sgl>
// A C++ engine's path tracer builds each pixel's primary ray by unprojecting
// its clip-space position at the near plane (reversed depth: z = 1) and at the
// far plane (z = 0) through the inverse view-projection: the ray starts on the
// near plane and runs to the far one. For a perspective camera that ray passes
// through the camera position; for an orthographic one all rays are parallel
// and start across the near plane.
space world;
space clip;

uniform projmap<clip, world> inverse_view_projection;
uniform point<world> camera_position;
in vec2 clipspace;
layout(location = 0) out vec4 outOrigin;
layout(location = 1) out vec4 outDirection;

void main() {
    vec4 unprojectedNEAR = inverse_view_projection * vec4(clipspace, 1.0, 1.0);
    unprojectedNEAR.xyz /= unprojectedNEAR.w;
    vec4 unprojectedFAR = inverse_view_projection * vec4(clipspace, 0.0, 1.0);
    unprojectedFAR.xyz /= unprojectedFAR.w;

    point<world> origin = unprojectedNEAR.xyz;
    direction<world> dir = normalize(unprojectedFAR.xyz - origin);
    outOrigin = vec4(origin, 0.001);
    outDirection = vec4(dir, 0.0);
}
