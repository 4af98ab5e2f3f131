#version 330 core
#include <safegi/prelude.sgl>
// Shadow-ray origin offset and the midpoint towards the light: the affine rules.
space world;

uniform point<world> lightPos;

in point<world> P;
in normal<world> N;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(N);
    vector<world> offset = 0.01 * meter * n;
    point<world> origin = P + offset;
    vector<world> toLight = lightPos - P;
    point<world> mid = P + 0.25 * (lightPos - P);
    float<length> travelled = length(mid - origin) + length(toLight);
    fragColor = vec4(vec3(travelled / meter), 1.0);
}
