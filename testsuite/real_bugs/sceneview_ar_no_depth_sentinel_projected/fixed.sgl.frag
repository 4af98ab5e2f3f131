#version 330 core
#include <safegi/prelude.sgl>
// An Android AR library's camera-stream material writes the real world's
// depth so virtual objects are occluded by it: the AR session's depth image
// (millimetres) places a point on the camera's axis, projected to get the
// fragment depth. A texel of 0 means "no depth here"; it is sent to the far
// plane (0 in this reverse-Z depth buffer) instead of being projected, since
// a point at the eye has w = 0.
space view;
space clip;

uniform projmap<view, clip> clipFromView;
uniform sampler2D<float<length in millimeter>> depthImage;

in vec2 depthUv;
out vec4 fragColor;

void main() {
    float<length in millimeter> depthMm = texture(depthImage, depthUv).x;
    if (depthMm <= 0.0) {
        gl_FragDepth = 0.0;
        fragColor = vec4(0.0);
        return;
    }
    float<length> depthM = depthMm in meter;
    vec4 h = clipFromView * vec4(0.0, 0.0, -depthM, 1.0);
    gl_FragDepth = h.z / h.w;
    fragColor = vec4(0.0);
}
