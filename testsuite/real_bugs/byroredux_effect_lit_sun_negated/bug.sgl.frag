#version 450
#include <safegi/prelude.sgl>
// A game-engine reimplementation's "effect lit" material path adds the sun's
// diffuse light; the sun direction it shares with every other lighting path
// points from the surface toward the sun, so N.L uses it as it is.
space world;

uniform direction<world, away> sunDirection;      // toward the sun
uniform spectrum<irradiance / proj> sunColor;       // on a surface facing the sun
uniform spectrum<1> effectColor;

layout(location = 0) in normal<world> fragNormal;
layout(location = 0) out vec4 outColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(fragNormal);
    vec3 Ldir = sunDirection;
    float NdotL = max(dot(N, -Ldir), 0.0);
    spectrum<radiance> lit = effectColor * INV_PI * sunColor * NdotL;
    outColor = vec4(lit, 1.0);
}
