#version 330 core
#include <safegi/prelude.sgl>
// A path tracer's next-event estimation on a spherical emitter: a point is
// chosen uniformly on the hemisphere of the sphere that faces the shading
// point, a density per area, which must be turned into a density per solid
// angle (distance^2 / cos at the emitter) before it divides the estimate.
space world;

uniform point<world> sphereCenter;
uniform float<length> sphereRadius;
uniform spectrum<radiance> emission;
uniform spectrum<brdf> bsdf;

in point<world, shaded> hitPos;
in normal<world> hitNormal;
in direction<world> sampledDir;          // the chosen point's direction from the centre
out vec4 contribution;

const float PI = 3.14159265358979;

void main() {
    vec3 lightPos = sphereCenter + sphereRadius * sampledDir;
    float<pdf_area> pdfArea = 1.0 / (2.0 * PI * sphereRadius * sphereRadius);
    vec3 toLight = lightPos - hitPos;
    float dist = length(toLight);
    vec3 wi = normalize(toLight);
    float cosLight = max(dot(sampledDir, -wi), 1e-4);
    vec3 N = normalize(hitNormal);
    float cosSurf = max(dot(N, wi), 0.0);
    float pdf = float<pdf_solid_angle>(pdfArea * dist * dist / cosLight);
    spectrum<radiance> L = emission * bsdf * cosSurf / pdf;
    contribution = vec4(L, 1.0);
}
