#version 330 core
#include <safegi/prelude.sgl>
// A game's shadow lookup takes five samples in a cross around the projected
// position to soften the shadow edge; the samples must be one shadow-map
// texel apart, 1 / resolution in texture coordinates, whatever the
// resolution the user picked.
uniform sampler2DShadow shadowMap;
uniform float shadowResolution;              // texels per side

in vec4 shadowCoord;                         // light clip coordinates, w = 1 (orthographic)
out vec4 fragColor;

void main() {
    vec3 coord = shadowCoord.xyz;
    float texel = 0.00025;
    float value = texture(shadowMap, coord);
    value += texture(shadowMap, coord + vec3( texel, 0.0, 0.0));
    value += texture(shadowMap, coord + vec3(-texel, 0.0, 0.0));
    value += texture(shadowMap, coord + vec3(0.0,  texel, 0.0));
    value += texture(shadowMap, coord + vec3(0.0, -texel, 0.0));
    fragColor = vec4(vec3(value / 5.0), 1.0);
}
