#version 330 core
#include <safegi/prelude.sgl>
// GLSL's reflect(w, n) written out, w - 2 n (n·w), mirrors an incident
// direction (toward the surface); a direction that points away from it (the
// light's direction from the surface) comes out pointing into the surface. The
// cosine may be a local that holds dot(n, w).
space view : eye;
in point<view, shaded> P;
in normal<view> N;
uniform point<view> lightPosition;
out vec3 mirrored;
out vec3 wrong;
void main() {
    vec3 n = normalize(N);
    vec3 I = normalize(P);
    vec3 l = normalize(lightPosition - P);
    float ndotl = dot(n, l);
    mirrored = (I - 2.0 * dot(n, I) * n) + (2.0 * ndotl * n - l);
    wrong = l - 2.0 * ndotl * n;
    gl_Position = vec4(P, 1.0);
}
