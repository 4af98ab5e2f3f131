#version 330 core
#include <safegi/prelude.sgl>
// A normal interpolated across a triangle is shorter than 1 between the
// vertices: a cosine, an offset along it, or a declared normal needs
// normalize() first. A flat input is not interpolated; length() and
// normalize() take it as it is.
space world;
uniform direction<world> toLight;
uniform float<length> bias;
in point<world> P;
in normal<world> vN;
flat in normal<world> faceN;
out vec4 c;
float<proj> lambert(normal<world> n) { return max(dot(n, toLight), 0.0); }
// A function that normalizes its parameter wherever it reads it takes one that is not unit.
float<proj> lambertOfAny(normal<world> n) { vec3 unit = normalize(n); return max(dot(unit, toLight), 0.0); }
void main() {
    normal<world> n = normalize(vN);
    float<proj> good = max(dot(n, toLight), 0.0) + max(dot(faceN, toLight), 0.0) + lambert(n);
    float shrink = length(vN);
    float<proj> cosine = max(dot(vN, toLight), 0.0);
    point<world> lifted = P + vN * bias;
    float<proj> viaFunction = lambert(vN);
    float<proj> normalizedInside = lambertOfAny(vN);
    normal<world> declared = vN;
    c = vec4(shrink * (good + cosine + viaFunction + normalizedInside), declared.x, 0.0, 1.0);
}
