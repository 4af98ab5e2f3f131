#version 330 core
#include <safegi/prelude.sgl>
// Lighting in world space; the light's position also arrives in object space.
space world;
space object;

uniform point<world> lightPos;
uniform point<object> lightPosObject;
uniform spectrum<intensity> lightI;
uniform spectrum<brdf> Kd;

in point<world, shaded> P;                   // the point being shaded
in normal<world> N;
in normal<object> nObject;
out vec4 fragColor;

float<length> distanceTo(point<world> a, point<world> b) { return length(a - b); }

void main() {
    normal<world> n = normalize(N);
    vector<world, away> toLight = lightPos - P;
    direction<world, away> wi = normalize(toLight);
    float<proj> cosTheta = max(dot(n, wi), 0.0);
    float<length> d = distanceTo(lightPosObject, P);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> L = Kd * lightI * cosTheta * falloff;
    fragColor = vec4(L, 1.0);
}
