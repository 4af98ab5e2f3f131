#version 330 core
#include <safegi/prelude.sgl>
// Blinn-Phong: directions are unit vectors, and only normalize() makes one.
space world;

uniform point<world> lightPos;
uniform point<world> eyePos;
uniform spectrum<radiance> Li;
uniform float<1> shininess;

in point<world, shaded> P;
in normal<world> N;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(N);
    vector<world, away> toLight = lightPos - P;
    direction<world, away> wi = normalize(toLight);
    direction<world, away> wo = normalize(eyePos - P);
    direction<world> h = normalize(wi + wo);
    direction<world, away> r = reflect(-wi, n);
    float spec = pow(max(dot(n, h), 0.0) / max(dot(n, wo), 0.0), shininess) * max(dot(r, wo), 0.0);
    fragColor = vec4(Li * spec, 1.0);
}
