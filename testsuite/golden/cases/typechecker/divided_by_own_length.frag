#version 330 core
#include <safegi/prelude.sgl>
// A vector divided by its own length is normalize() written out: `L / length(L)`,
// `L / d` and `L /= d` with `float d = length(L)`, while L still holds the value
// that was measured. Once L is written (before the division, or anywhere in an
// enclosing loop, whose next iteration sees it), or for part of L, it is not.
space world;
uniform point<world> lightPos;
uniform normal<world> n;
in point<world, shaded> P;
out vec4 c;
void main() {
    vec3 toLight = lightPos - P;
    float d = length(toLight);
    float<proj> byLength = dot(n, toLight / length(toLight));
    float<proj> byDistance = dot(n, toLight / d);
    vec3 L = lightPos - P;
    float dist = length(L);
    L /= dist;
    float<proj> inPlace = dot(n, L);

    vec3 moved = lightPos - P;
    float reach = length(moved);
    moved = moved * 2.0;
    float<proj> stale = dot(n, moved / reach);

    vec3 step = lightPos - P;
    float stepLength = length(step);
    float<proj> sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        sum += dot(n, step / stepLength);
        step *= 0.5;
    }
    float<proj> partOf = dot(n, vec3(toLight.xy / d, 0.0));
    c = vec4(byLength + byDistance + inPlace + stale, sum, partOf, 1.0);
}
