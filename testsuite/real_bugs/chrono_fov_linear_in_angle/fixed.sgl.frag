#version 330 core
#include <safegi/prelude.sgl>
// A simulator's pinhole depth camera: primary rays through the image plane at
// unit distance, whose half-width is tan(hFOV / 2), the tangent of the half
// angle (not the angle itself rescaled).
space world;

uniform float<angle> hFOV;                          // horizontal field of view
uniform vec2 resolution;
uniform point<world> cameraOrigin;
uniform direction<world> cameraForward;
uniform direction<world> cameraLeft;
uniform direction<world> cameraUp;
uniform float<length> maxDepth;

out vec4 depthOut;

float<length> traceScene(point<world> origin, direction<world> dir) {
    float down = -dir.y;                            // the ground is the plane y = 0
    return down > 0.0 ? min(origin.y / down, maxDepth) : maxDepth;
}

void main() {
    vec2 d = (gl_FragCoord.xy / resolution) * 2.0 - 1.0;
    float<1> h_factor = tan(hFOV / 2.0);
    float v_factor = h_factor * resolution.y / resolution.x;
    vec3 ray = normalize(cameraForward - d.x * h_factor * cameraLeft + d.y * v_factor * cameraUp);
    float<length> depth = traceScene(cameraOrigin, ray);
    depthOut = vec4(depth / maxDepth);
}
