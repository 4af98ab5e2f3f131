#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform spectrum<intensity> lightI;   // W/sr
uniform point<world> lightPos;
in point<world> P;
in normal<world> N;
out vec4 color;
void main() {
    vector<world> toLight = lightPos - P;
    float<length> d = length(toLight);
    float<proj> cosTheta = max(dot(normalize(N), normalize(toLight)), 0.0);
    // dω/dA = cos θ / d²: a solid angle per projected area
    float<solid_angle / (area * proj)> G = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<irradiance> E = lightI * G;
    color = vec4(E, 1.0);
}
