#version 330 core
#include <safegi/prelude.sgl>
// A shader library's small PBR model: the diffuse light at a point is the
// light's irradiance on the surface plus the ambient irradiance from the
// scene's spherical harmonics, both reflected by the Lambert BRDF (the
// indirect term is added to the direct one, not multiplied into it).
space world;

uniform point<world> u_lightPosition;
uniform spectrum<irradiance / proj> u_lightColor;     // on a surface facing the light
uniform spectrum<irradiance> u_SH[4];                 // bands 0 and 1, irradiance
uniform spectrum<1> u_albedo;

in point<world, shaded> v_position;
in normal<world> v_normal;
out vec4 fragColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

spectrum<irradiance> sphericalHarmonics(normal<world> n) {
    return u_SH[0] + u_SH[1] * n.y + u_SH[2] * n.z + u_SH[3] * n.x;
}

void main() {
    vec3 N = normalize(v_normal);
    vec3 L = normalize(u_lightPosition - v_position);
    float NoL = max(dot(N, L), 0.0);
    vec3 direct = u_lightColor * NoL;
    vec3 indirect = sphericalHarmonics(N);
    spectrum<radiance> color = u_albedo * INV_PI * (direct + indirect);
    fragColor = vec4(color, 1.0);
}
