#version 330 core
#include <safegi/prelude.sgl>
// A scientific plotting library's mesh shading filter: a face whose normal
// points away from the viewer (a mesh wound the other way) is shaded with the
// normal flipped toward the viewer, and otherwise with the normal as given,
// before the diffuse term of a directional light.
space view : eye;

uniform direction<view, toward> u_light_dir;       // the light's travel direction
uniform spectrum<irradiance / proj> u_light_color;
uniform spectrum<brdf> u_diffuse_color;
uniform spectrum<radiance> u_ambient;

in point<view, shaded> v_pos;
in normal<view> v_normal;
out vec4 fragColor;

void main() {
    vec3 eye = normalize(-v_pos);
    vec3 nIn = normalize(v_normal);
    vec3 n;
    if (dot(nIn, eye) < 0.0)
        n = -nIn;
    n = nIn;
    float cosL = max(dot(n, -u_light_dir), 0.0);
    spectrum<radiance> L = u_ambient + u_diffuse_color * u_light_color * cosL;
    fragColor = vec4(L, 1.0);
}
