#version 330 core
#include <safegi/prelude.sgl>
// An ocean renderer's refraction: the scene behind the water is sampled at a
// screen position displaced by the surface normal's slope. The displacement
// is a distance on the water, so on screen it shrinks with the distance to
// the camera: divided by the view depth, a camera high above the sea sees
// small ripples, not screen-sized ones.
space world;
space clip;

uniform sampler2D sceneColor;
uniform float<length> refractionStrength;    // displacement on the water per unit of slope

in normal<world> vNormal;
in hpoint<clip> screenPos;                   // clip coordinates of the surface
in float<length> viewDepth;                  // distance along the camera's forward axis
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    vec2 uv = screenPos.xy / screenPos.w * 0.5 + 0.5;
    vec2 offset = n.xz * refractionStrength / viewDepth;
    fragColor = vec4(texture(sceneColor, uv + offset).rgb, 1.0);
}
