#version 330 core
#include <safegi/prelude.sgl>
#define RADIANCE(brdf, E) ((brdf) * (E))
uniform spectrum<brdf> Kd;
uniform spectrum<radiance> Li;
out vec4 c;
void main() {
    spectrum<radiance> L = RADIANCE(Kd, Li);
    c = vec4(L, 1.0);
}
