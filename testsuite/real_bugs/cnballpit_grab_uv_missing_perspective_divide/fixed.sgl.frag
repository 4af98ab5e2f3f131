#version 330 core
#include <safegi/prelude.sgl>
// A VRChat world's screen-space effect (a Unity HLSL shader, rewritten as
// GLSL): a world position reconstructed from the depth buffer is projected
// back to the screen, and the depth buffer is read at that pixel and at its
// neighbours, one pixel apart, to estimate the depth gradient. The grab-screen
// position (ComputeGrabScreenPos: xy = (clip.xy + clip.w) / 2, zw = clip.zw)
// is divided by its w before the pixel offsets are added.
space world;
space clip;

uniform projmap<world, clip> clipFromWorld;
uniform sampler2D depthTexture;
uniform vec2 screenSize;                          // pixels
uniform float nx;                                 // offset in pixels

in point<world> wpos;
out vec4 fragColor;

float linearEyeDepth(float z) { return 1.0 / (z * 0.99 + 0.01); }

void main() {
    hpoint<clip> screenPos2 = clipFromWorld * vec4(wpos, 1.0);
    vec4 dgpos2 = vec4((screenPos2.xy + screenPos2.w) * 0.5, screenPos2.zw);
    float pd2 = 1.0 / dgpos2.w;
    dgpos2 *= pd2;

    vec2 offsetM = dgpos2.xy;
    vec2 offsetL = dgpos2.xy + vec2(nx, 0.0) / screenSize;
    vec2 offsetR = dgpos2.xy + vec2(-nx, 0.0) / screenSize;
    float M = abs(linearEyeDepth(textureProj(depthTexture, vec4(offsetM, dgpos2.zw)).r));
    float L = abs(linearEyeDepth(textureProj(depthTexture, vec4(offsetL, dgpos2.zw)).r));
    float R = abs(linearEyeDepth(textureProj(depthTexture, vec4(offsetR, dgpos2.zw)).r));
    float X = ((R - M) + (M - L)) * 0.5;
    fragColor = vec4(normalize(vec3(X, 0.0, 0.01)) * 0.5 + 0.5, 1.0);
}
