#version 330 core
#include <safegi/prelude.sgl>
// Diffuse scattering in a small GPU path tracer: the new ray heads from the hit
// point to hit + normal + a random unit vector, which is a cosine-weighted
// direction about the normal.
space world;

flat in point<world> hitPos;
flat in normal<world> hitNormal;
flat in uint seed;
out vec4 scatterDir;

float nextRandom(inout uint state) {
    state = state * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return float((word >> 22u) ^ word) / 4294967295.0;
}

vec3 randomInUnitSphere(inout uint state) {
    vec3 p;
    do {
        p = 2.0 * vec3(nextRandom(state), nextRandom(state), nextRandom(state)) - vec3(1.0);
    } while (dot(p, p) >= 1.0);
    return p;
}

vec3 randomUnitVector(inout uint state) {
    return randomInUnitSphere(state);
}

void main() {
    uint state = seed;
    point<world> target = hitPos + hitNormal + randomUnitVector(state);
    direction<world> dir = normalize(target - hitPos);
    scatterDir = vec4(dir, 0.0);
}
