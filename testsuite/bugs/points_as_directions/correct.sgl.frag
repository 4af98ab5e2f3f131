#version 330 core
#include <safegi/prelude.sgl>
// A spot light: the light and the eye are points; the directions towards them
// are normalized differences of points.
space world;

uniform point<world> lightPos;
uniform direction<world> spotAxis;                     // where the spot points
uniform float cosCutoff;                               // cosine of the spot's half angle
uniform spectrum<intensity> lightI;
uniform point<world> eyePos;
uniform spectrum<brdf> Kd;
uniform spectrum<brdf> Ks;
uniform float shininess;

in point<world, shaded> P;                     // the point being shaded
in normal<world> N;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(N);
    vector<world, away> toLight = lightPos - P;
    float<length> d = length(toLight);
    direction<world, away> wi = normalize(toLight);
    direction<world, away> wo = normalize(eyePos - P);
    float<proj> cosTheta = max(dot(n, wi), 0.0);
    float spot = step(cosCutoff, dot(-wi, spotAxis));
    direction<world> h = normalize(wi + wo);
    float highlight = pow(max(dot(n, h), 0.0), shininess);  // a lobe, not a projection
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> L = (Kd + Ks * highlight) * lightI * cosTheta * falloff * spot;
    fragColor = vec4(L, 1.0);
}
