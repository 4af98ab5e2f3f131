#version 300 es
#include <safegi/prelude.sgl>
// Web engine's diffuse image-based lighting: irradiance from nine spherical-
// harmonics coefficients (pre-scaled on the CPU) evaluated at the world normal.
// The coefficients were projected from a cube map whose faces follow the
// left-handed cube-map convention, so the normal's x is mirrored first.
precision highp float;
space world;

uniform spectrum<irradiance> u_env_sh[9];
uniform spectrum<brdf> u_diffuseBRDF;        // albedo / pi

in normal<world> v_normal;
out vec4 fragColor;

spectrum<irradiance> getLightProbeIrradiance(spectrum<irradiance> sh[9], normal<world> N) {
    vec3 n = N;
    n.x = -n.x;
    vec3 result = sh[0]
        + sh[1] * n.y + sh[2] * n.z + sh[3] * n.x
        + sh[4] * (n.y * n.x) + sh[5] * (n.y * n.z)
        + sh[6] * (3.0 * n.z * n.z - 1.0)
        + sh[7] * (n.z * n.x) + sh[8] * (n.x * n.x - n.y * n.y);
    return max(result, vec3(0.0));
}

void main() {
    vec3 irradiance = getLightProbeIrradiance(u_env_sh, normalize(v_normal));
    spectrum<radiance> L = u_diffuseBRDF * irradiance;
    fragColor = vec4(L, 1.0);
}
