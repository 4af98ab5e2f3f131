#version 330 core
#include <safegi/prelude.sgl>
// A console emulator's generated vertex lighting for one directional light:
// the game writes the light's direction register with any length, so the
// shader normalizes it before the cosine with the vertex normal weighs the
// light color. The console's colors are plain numbers.
space object;
space world;
space clip;

uniform vector<world, 1> u_light_dir;     // toward the light, as the game wrote it
uniform spectrum<1> u_light_color;
uniform spectrum<1> u_material_color;
uniform map<object, world> u_model;
uniform projmap<world, clip> u_view_proj;

in point<object> rawpos;
in normal<object> rawnorm;
out vec4 colors_0;

void main() {
    vec4 pos = u_model * vec4(rawpos, 1.0);
    vec3 _norm0 = normalize((vec4(rawnorm, 0.0) * inverse(u_model)).xyz);
    vec3 ldir = u_light_dir;
    float cosL = max(dot(ldir, _norm0), 0.0);
    vec3 lacc = u_material_color * u_light_color * cosL;
    colors_0 = vec4(lacc, 1.0);
    gl_Position = u_view_proj * pos;
}
