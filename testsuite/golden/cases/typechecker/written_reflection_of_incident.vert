#version 330 core
#include <safegi/prelude.sgl>
// The reflection written out, 2 n (n·w) - w, mirrors an outgoing direction
// (one that points away from the surface); the eye's incident ray points
// toward it, and its reflection is reflect(I, n).
space view : eye;
in point<view, shaded> P;
in normal<view> N;
out vec3 mirrored;
out vec3 wrong;
void main() {
    vec3 n = normalize(N);
    vec3 I = normalize(P);
    vec3 wo = -I;
    mirrored = normalize(2.0 * n * dot(n, wo) - wo) + reflect(I, n);
    wrong = 2.0 * dot(I, n) * n - I;
    gl_Position = vec4(P, 1.0);
}
