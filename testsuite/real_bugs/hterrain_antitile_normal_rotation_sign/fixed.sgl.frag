#version 450
#include <safegi/prelude.sgl>
// A terrain plugin's anti-tiling sampling: the detail textures are read at
// texture coordinates rotated by a per-tile angle, and the sampled normal
// (y up, x and z horizontal, in the terrain's world axes) is rotated back by
// the same angle before lighting.
space world;

uniform sampler2D normalTex;
uniform float<angle> tileAngle;
uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<brdf> albedo;

in vec2 uv;
out vec4 fragColor;

vec2 rotate2(vec2 v, float c, float s) {
    return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

void main() {
    float cosa = cos(tileAngle);
    float sina = sin(tileAngle);
    vec2 ruv = rotate2(uv, cosa, sina);
    normal<world> n = normalize(texture(normalTex, ruv).xzy * 2.0 - 1.0);
    n.xz = -rotate2(n.xz, cosa, sina);
    float cosL = max(dot(normalize(n), lightDir), 0.0);
    fragColor = vec4(albedo * lightIrradiance * cosL, 1.0);
}
