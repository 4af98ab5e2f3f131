#version 330 core
#include <safegi/prelude.sgl>
// An accumulator that starts at zero takes the quantity of what it collects,
// in a loop too; what it collects afterwards is checked against that, and so
// is where the sum goes.
uniform spectrum<radiance> Li[4];
uniform spectrum<irradiance> E;
out spectrum<radiance> L;
out spectrum<radiance> L2;
void main() {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 4; ++i) sum += Li[i];
    L = sum;
    vec3 mixedUp = vec3(0.0);
    mixedUp += Li[0];
    mixedUp += E;
    vec3 wrong = vec3(0.0);
    for (int i = 0; i < 4; ++i) wrong += E;
    L2 = wrong;
}
