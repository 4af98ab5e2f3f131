#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// A shader library's depth helper, used by its post-processing (fog, SSAO,
// depth of field): a perspective depth-buffer value in [0, 1] back to the
// distance in front of the camera, 2 n f / (f + n - z_ndc (f - n)).
uniform sampler2D colorTex;
uniform sampler2D depthTex;
uniform float<length> cameraNear;
uniform float<length> cameraFar;
uniform float<length> fogStart;
uniform float<length> fogEnd;
uniform vec3 fogColor;

in vec2 vUv;
out vec4 fragColor;

float<length> linearizeDepth(float<1> depth, float<length> near, float<length> far) {
    float ndc = depth * 2.0 - 1.0;
    return (2.0 * near) / (far + near - ndc * (far - near));
}

void main() {
    float<length> z = linearizeDepth(texture(depthTex, vUv).r, cameraNear, cameraFar);
    float fog = clamp((z - fogStart) / (fogEnd - fogStart), 0.0, 1.0);
    fragColor = vec4(mix(texture(colorTex, vUv).rgb, fogColor, fog), 1.0);
}
