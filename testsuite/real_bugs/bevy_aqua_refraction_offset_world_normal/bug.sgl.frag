#version 450
#include <safegi/prelude.sgl>
// A water plugin's screen-space refraction: the background behind the water
// surface is sampled at a screen position displaced by the rippled surface
// normal. The screen's axes are the camera's, so the world-space normal is
// first carried to view space and its x and y displace the sample.
space world;
space view : eye;

uniform sampler2D sceneColor;
uniform rigidmap<world, view> viewFromWorld;
uniform float refractionStrength;            // screen fraction per unit of normal tilt
uniform vec2 invScreenSize;

in normal<world> rippleNormal;
out vec4 fragColor;

void main() {
    normal<world> nWorld = normalize(rippleNormal);
    normal<view> nView = nWorld in view;
    vec2 screenUv = gl_FragCoord.xy * invScreenSize;
    vec2 refractUv = clamp(screenUv + nWorld.xz * refractionStrength, vec2(0.001), vec2(0.999));
    fragColor = vec4(texture(sceneColor, refractUv).rgb, 1.0);
}
