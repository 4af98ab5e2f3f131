#version 300 es
#include <safegi/prelude.sgl>
// The diffuse bounce of a WebGL path tracer: a direction is drawn in the
// hemisphere around the normal, and the path throughput is multiplied by
// brdf * cos(theta) / pdf. Drawn uniformly, pdf = 1 / (2 pi), so the weight
// is albedo * 2 cos(theta), as the shader writes it in one line.
precision highp float;
space world;

const float PI = 3.14159265358979;

uniform spectrum<1> surfaceColor;                 // diffuse albedo
uniform spectrum<radiance> skyRadiance;

in normal<world> nl;                              // faces the incoming ray
out vec4 fragColor;

vec3 randomDirectionInHemisphere(vec3 n, inout float seed) {
    seed = fract(sin(seed) * 43758.5453);
    float up = seed;
    float over = sqrt(max(0.0, 1.0 - up * up));
    float around = fract(seed * 7.31) * 2.0 * PI;
    vec3 u = normalize(cross(abs(n.x) > 0.1 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
    vec3 v = cross(n, u);
    return normalize(u * cos(around) * over + v * sin(around) * over + n * up);
}

vec3 randomCosWeightedDirectionInHemisphere(vec3 n, inout float seed) {
    seed = fract(sin(seed) * 43758.5453);
    float up = sqrt(seed);
    float over = sqrt(max(0.0, 1.0 - up * up));
    float around = fract(seed * 7.31) * 2.0 * PI;
    vec3 u = normalize(cross(abs(n.x) > 0.1 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
    vec3 v = cross(n, u);
    return normalize(u * cos(around) * over + v * sin(around) * over + n * up);
}

void main() {
    float seed = gl_FragCoord.x * 0.618 + gl_FragCoord.y;
    vec3 mask = vec3(1.0);
    for (int depth = 0; depth < 4; depth++) {
        spectrum<brdf> f = surfaceColor / PI;
        direction<world> wi = randomCosWeightedDirectionInHemisphere(nl, seed);
        float<pdf_solid_angle> pdf = 1.0 / PI;
        float cosTheta = max(0.0, dot(wi, normalize(nl)));
        mask *= f * cosTheta / pdf;
    }
    spectrum<radiance> L = mask * skyRadiance;
    fragColor = vec4(L, 1.0);
}
