#version 300 es
#include <safegi/prelude.sgl>
// A WebGPU/WebGL path tracer's environment importance sampling: a pass writes
// each texel's weight for the equirectangular map's marginal and conditional
// CDFs. A texel covers a solid angle proportional to sin(theta) of its row, so
// the weight is its luminance times sin(theta); the pdf per solid angle later
// divides by the same sin(theta).
precision highp float;

uniform sampler2D<spectrum<radiance>> envMap;
uniform vec2 envSize;
out vec4 weightOut;

const float PI = 3.14159265358979;

void main() {
    vec2 uv = gl_FragCoord.xy / envSize;
    vec3 L = texture(envMap, uv).rgb;
    float luminance = dot(L, vec3(0.2126, 0.7152, 0.0722));
    float sinTheta = sin(PI * uv.y);
    float weight = luminance * sinTheta;
    weightOut = vec4(weight);
}
