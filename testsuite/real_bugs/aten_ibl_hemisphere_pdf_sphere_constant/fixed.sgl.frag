#version 450
#include <safegi/prelude.sgl>
// Next-event estimation on an image-based light in a GPU path tracer (CUDA
// kernels, rewritten as GLSL): the light direction is drawn uniformly on the
// hemisphere above the surface, so its density is 1 / (2 pi) per steradian,
// and the environment's radiance is weighted by brdf * cos / pdf.
space world;

const float AT_MATH_PI = 3.14159265358979;

uniform samplerCube<spectrum<radiance>, world> envmap;
uniform spectrum<brdf> bsdf;

in normal<world> orienting_normal;
in vec2 u;                                        // two uniform random numbers
out vec4 fragColor;

direction<world> sampleHemisphere(normal<world> n, vec2 r) {
    float cosTheta = r.x;
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * AT_MATH_PI * r.y;
    vec3 t = normalize(cross(abs(n.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
    vec3 b = cross(n, t);
    return direction<world>(normalize(t * cos(phi) * sinTheta + b * sin(phi) * sinTheta + n * cosTheta));
}

void main() {
    normal<world> n = normalize(orienting_normal);
    direction<world> dir = sampleHemisphere(n, u);
    // Sample one point on the hemisphere.
    float<pdf_solid_angle> pdf = 1.0 / (2.0 * AT_MATH_PI);
    spectrum<radiance> Le = texture(envmap, dir).rgb;
    float cosShadow = max(dot(n, dir), 0.0);
    spectrum<radiance> contrib = bsdf * Le * cosShadow / pdf;
    fragColor = vec4(contrib, 1.0);
}
