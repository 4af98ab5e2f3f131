#version 330 core
#include <safegi/prelude.sgl>
// 'toward' means pointing at the shaded point: a direction from the surface to
// the light declared toward is read as the light's travel direction, and its
// Lambert cosine bounded at 0 is refused. The hint offers both fixes: negate it
// where it is used, or declare it away if that is what it is.
space world;
uniform direction<world, toward> lightDir;   // meant: from the surface to the light
uniform spectrum<irradiance / proj> sunIrradiance;
uniform spectrum<brdf> albedo;
in normal<world> vNormal;
out vec4 color;
void main() {
    vec3 n = normalize(vNormal);
    float cosL = max(dot(n, lightDir), 0.0);
    color = vec4(albedo * sunIrradiance * cosL, 1.0);
}
