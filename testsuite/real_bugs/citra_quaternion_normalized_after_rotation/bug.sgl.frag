#version 330 core
#include <safegi/prelude.sgl>
// A handheld-console emulator's generated fragment lighting: the console
// interpolates a per-vertex rotation quaternion; the fragment normalizes it
// (a linear blend of unit quaternions is not unit) and then rotates the
// surface-local normal into view space with it.
space view : eye;

uniform point<view> light_position;
uniform spectrum<irradiance / proj> light_diffuse;
uniform spectrum<brdf> material_diffuse;

in vec4 normquat;                         // interpolated rotation quaternion
in point<view, shaded> fragment_position;
out vec4 color;

// Rotate the vector v by the quaternion q
vec3 quaternion_rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

void main() {
    vec3 surface_normal = vec3(0.0, 0.0, 1.0);
    normal<view> normal = normal<view>(normalize(quaternion_rotate(normquat, surface_normal)));
    direction<view, away> light_vector = normalize(light_position - fragment_position);
    float dot_product = max(dot(light_vector, normal), 0.0);
    spectrum<radiance> diffuse_sum = material_diffuse * light_diffuse * dot_product;
    color = vec4(diffuse_sum, 1.0);
}
