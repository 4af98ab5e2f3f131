#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// An engine's indirect light given as spherical-harmonics coefficients of the
// environment's radiance (bands 0 and 1): the irradiance at a normal is the
// SH expansion convolved with the clamped cosine, A0 = pi, A1 = 2 pi / 3,
// each coefficient times its basis function. The engine's band-1 basis
// functions carry a negative sign (-K1 y, -K1 z, -K1 x).
space world;

const float PI = 3.14159265358979;
const float K0 = 0.282095;
const float K1 = 0.488603;

uniform spectrum<radiance> shRadiance[4];
uniform vec3 diffuseColor;

in normal<world> vNormal;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(vNormal);
    spectrum<irradiance> E = shRadiance[0] * K0 * PI
        + (shRadiance[1] * (K1 * n.y) + shRadiance[2] * (K1 * n.z) + shRadiance[3] * (K1 * n.x)) * (2.0 * PI / 3.0);
    fragColor = vec4(diffuseColor / PI * max(E, vec3(0.0)), 1.0);
}
