#version 450
// runtime_vk's test shader for arrays of std430 structs: the area of each
// triangle of a scene, uploaded as the host laid it out.
#include <safegi/prelude.sgl>

space world;

layout(local_size_x = 1) in;

struct Triangle {
    point<world> a;
    point<world> b;
    point<world> c;
    uint material;
};

layout(set = 0, binding = 0, std430) readonly buffer Triangles { Triangle triangles[]; } scene;
layout(set = 0, binding = 1, std430) writeonly buffer Areas { float<area> areas[]; } result;
// Moves the whole scene (which leaves every area as it was).
layout(push_constant) uniform Frame { vector<world> offset; } frame;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    const Triangle t = scene.triangles[i];
    const point<world> a = t.a + frame.offset;
    const point<world> b = t.b + frame.offset;
    const point<world> c = t.c + frame.offset;
    result.areas[i] = 0.5 * length(cross(b - a, c - a)) * float(t.material + 1u);
}
