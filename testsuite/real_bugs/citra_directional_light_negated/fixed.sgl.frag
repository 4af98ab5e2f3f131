#version 330 core
#include <safegi/prelude.sgl>
// A handheld-console emulator's generated fragment lighting. For a directional
// light the console's light register holds the direction toward the light;
// for a positional light its view-space position. Either way the light vector
// points from the fragment toward the light, and N.L weighs its diffuse color.
space view : eye;

uniform bool light_directional;
uniform direction<view, away> light_direction;   // directional: toward the light
uniform point<view> light_position;              // positional
uniform spectrum<irradiance / proj> light_diffuse;
uniform spectrum<brdf> material_diffuse;

in point<view, shaded> fragment_position;
in normal<view> surface_normal;
out vec4 color;

void main() {
    vec3 normal = normalize(surface_normal);
    direction<view, away> light_vector;
    if (light_directional)
        light_vector = normalize(light_direction);
    else
        light_vector = normalize(light_position - fragment_position);
    float dot_product = max(dot(light_vector, normal), 0.0);
    spectrum<radiance> diffuse_sum = material_diffuse * light_diffuse * dot_product;
    color = vec4(diffuse_sum, 1.0);
}
