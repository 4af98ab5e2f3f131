#version 460
#include <safegi/prelude.sgl>
// A ray-tracing tutorial's path tracer, closest hit: the next direction is
// drawn with a cosine-weighted hemisphere sample, whose density is
// cos(theta) / pi; the throughput is BRDF * cos(theta) / pdf.
space world;

const float M_PI = 3.14159265358979323846;

uniform spectrum<1> diffuse;
uniform spectrum<radiance> emittance;

flat in normal<world> worldNormal;
flat in direction<world> rayDirection;          // the cosine-weighted sample
out vec4 hitValue;                              // rgb: emitted, a: unused
out vec4 weight;

void main() {
    float cos_theta = dot(rayDirection, worldNormal);
    float<pdf_solid_angle> p = 1.0 / M_PI;
    spectrum<brdf> BRDF = diffuse / M_PI;
    spectrum<1> throughput = BRDF * cos_theta / p;
    hitValue = vec4(emittance, 1.0);
    weight = vec4(throughput, 1.0);
}
