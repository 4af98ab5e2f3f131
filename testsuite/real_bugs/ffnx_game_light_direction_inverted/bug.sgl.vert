#version 330 core
#include <safegi/prelude.sgl>
// A game renderer replacement's GPU version of the original game lighting:
// three directional lights whose stored vectors are the directions the light
// travels, so each cosine is taken with the vector reversed (toward the
// light), and an ambient color. Colors are plain numbers, as the game's are.
space world;
space clip;

uniform direction<world, toward> gameLightDir1;   // travel direction of light 1
uniform direction<world, toward> gameLightDir2;
uniform direction<world, toward> gameLightDir3;
uniform vec3<1> gameLightColor1;
uniform vec3<1> gameLightColor2;
uniform vec3<1> gameLightColor3;
uniform vec3<1> gameAmbientColor;
uniform projmap<world, clip> viewProj;

in point<world> a_position;
in normal<world> a_normal;
out vec4 v_color0;

void main() {
    vec3 n = normalize(a_normal);
    float d1 = max(dot(n, gameLightDir1), 0.0);
    float d2 = max(dot(n, gameLightDir2), 0.0);
    float d3 = max(dot(n, gameLightDir3), 0.0);
    vec3 light = gameAmbientColor + d1 * gameLightColor1 + d2 * gameLightColor2 + d3 * gameLightColor3;
    v_color0 = vec4(light, 1.0);
    gl_Position = viewProj * vec4(a_position, 1.0);
}
