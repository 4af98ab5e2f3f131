#version 330 core
#include <safegi/prelude.sgl>
// A ray tracer's cosine-weighted hemisphere sampling (pdf cos(theta) / pi):
// z = sqrt(1 - r2), and the horizontal part has length sin(theta) = sqrt(r2).
space local;                                          // z along the normal
space world;

uniform rigidmap<local, world> worldFromLocal;       // orthonormal basis around the normal
uniform samplerCube<spectrum<radiance>> sky;
uniform spectrum<1> albedo;
uniform vec2 xi;                                      // two uniform random numbers

out vec4 fragColor;

const float PI = 3.141592653589793;

direction<local> randomCosineDirection(float r1, float r2) {
    float z = sqrt(1.0 - r2);
    float phi = 2.0 * PI * r1 * radian;
    float x = cos(phi) * 2.0 * sqrt(r2);
    float y = sin(phi) * 2.0 * sqrt(r2);
    return direction<local>(x, y, z);
}

void main() {
    vec3 wi = worldFromLocal * randomCosineDirection(xi.x, xi.y);
    // brdf * Li * cos / pdf = (albedo / pi) * Li * cos / (cos / pi) = albedo * Li
    spectrum<radiance> L = albedo * texture(sky, wi).rgb;
    fragColor = vec4(L, 1.0);
}
