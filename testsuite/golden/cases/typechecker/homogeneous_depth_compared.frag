#version 330 core
#include <safegi/prelude.sgl>
// A homogeneous coordinate before the divide is no depth: z·w compared with a
// stored depth is the forgotten perspective divide of a shadow lookup.
space world;
space light_clip;
uniform projmap<world, light_clip> lightClipFromWorld;
uniform float<1> stored;
in point<world> P;
out vec4 c;
void main() {
    hpoint<light_clip> h = lightClipFromWorld * P;
    float currentDepth = h.z * 0.5 + 0.5;
    float lit = currentDepth > stored ? 0.0 : 1.0;
    float ndcDepth = h.z / h.w * 0.5 + 0.5;
    c = vec4(lit, ndcDepth > stored ? 0.0 : 1.0, 0.0, 1.0);
}
