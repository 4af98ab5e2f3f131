#version 330 core
#include <safegi/prelude.sgl>
// Shadow mapping and screen-space effects: a projective map gives homogeneous
// points, and their coordinates are positions only after the divide by w.
space world;
space light_clip;
space clip;

uniform projmap<world, light_clip> lightClipFromWorld;
uniform projmap<world, clip> clipFromWorld;
uniform sampler2D<float<1>> shadowDepth;               // window-space depth in [0, 1]
uniform sampler2D<spectrum<radiance>> previousFrame;

in point<world> P;
out vec4 fragColor;

void main() {
    hpoint<light_clip> hLight = lightClipFromWorld * P;
    hpoint<clip> hCam = clipFromWorld * P;
    vec3 ndc = hLight.xyz / hLight.w;                   // normalized device coordinates
    vec2 shadowUv = ndc.xy * 0.5 + 0.5;
    float<1> depth = float<1>(ndc.z * 0.5 + 0.5);
    float<1> stored = texture(shadowDepth, shadowUv).r;
    float lit = depth - 0.002 <= stored ? 1.0 : 0.0;
    vec2 screenUv = hCam.xy * 0.5 + 0.5;
    spectrum<radiance> history = spectrum<radiance>(texture(previousFrame, screenUv).rgb);
    fragColor = vec4(history * lit, 1.0);
}
