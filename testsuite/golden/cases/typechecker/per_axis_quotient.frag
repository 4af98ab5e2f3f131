#version 330 core
#include <safegi/prelude.sgl>
// A slab test divides by a ray direction's components: `1.0 / d` and
// `(lower - o) / d` are numbers per axis (per length, and lengths over a
// unit direction), no longer vectors of the space; a vector of another space
// is still told.
space world;
space object;
uniform point<world> lower;
uniform point<world> upper;
uniform point<world> origin;
uniform direction<world> d;
uniform vector<object> extentObject;
out vec4 c;
void main() {
    vec3 invD = 1.0 / d;
    vec3 t0 = (lower - origin) * invD;
    vec3 t1 = (upper - origin) / d;
    vec3 tNear = min(t0, t1);
    float<length> enter = max(max(tNear.x, tNear.y), tNear.z);
    vec3 wrong = extentObject / d;
    c = vec4(enter * invD, 1.0);
}
