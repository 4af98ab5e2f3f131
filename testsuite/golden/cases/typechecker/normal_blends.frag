#version 330 core
#include <safegi/prelude.sgl>
// Normals are covectors: a sum of normals of one space, weighted or not, is a
// normal of that space (two normal maps blended, a morph target's base normal
// plus weighted differences), of unit length only once normalized. The
// difference of two normals is a vector: its length is what an edge detector
// measures. And a unit vector moved into [0, 1] (n * 0.5 + 0.5) is the
// normal written as a colour: plain numbers.
space world;

uniform float<1> weight;
uniform float blend;
uniform direction<world, toward> toLight;

in normal<world> vNormal;
in normal<world> vDetail;

out normal<world> blended;
out vec4 encoded;

void main() {
    normal<world> n = normalize(vNormal);
    normal<world> detail = normalize(vDetail);
    blended = normalize(n + detail);
    blended = normalize(weight * n + (1.0 - weight) * detail);
    blended = normalize(n + blend * (detail - n));
    float edge = dot(n - detail, n - detail);
    encoded = vec4(n * 0.5 + 0.5, edge);
    encoded = vec4((detail + 1.0) * 0.5, 1.0);

    vec3 unnormalized = weight * n + (1.0 - weight) * detail;
    float cosine = max(dot(unnormalized, toLight), 0.0);
    encoded = vec4(cosine);
}
