#version 330 core
#include <safegi/prelude.sgl>
// A handheld-console emulator's hardware-transform vertex lighting (one point
// light): the cosine between the normal and the direction toward the light
// weighs the light's diffuse color, attenuated by 1 / (c + l d + q d^2)
// clamped to 1. The console's lights and colors are plain numbers.
space world;

uniform point<world> u_lightpos0;
uniform spectrum<1> u_lightdiffuse0;
uniform spectrum<1> u_matdiffuse;
uniform float<1> u_lightatt0_const;
uniform float<inv_length> u_lightatt0_linear;
uniform float<inv_area> u_lightatt0_quadratic;

in point<world, shaded> worldpos;      // u_world * a_position
in normal<world> worldnormal;          // normalize(u_world * a_normal)
out vec3<1> v_color0;

void main() {
    vector<world> toLight0 = u_lightpos0 - worldpos;
    float dot0 = dot(toLight0, worldnormal);
    float distance0 = length(toLight0);
    float lightScale0 = 1.0 / (u_lightatt0_const + u_lightatt0_linear * distance0
                               + u_lightatt0_quadratic * distance0 * distance0);
    if (lightScale0 > 1.0) lightScale0 = 1.0;
    vec3 diffuse0 = (u_lightdiffuse0 * u_matdiffuse) * (dot0 * lightScale0);
    v_color0 = diffuse0;
}
