// RAW
// ARGS: -V -o /dev/null
// Issue 46, class 4: a buffer_reference held in a push-constant or uniform block
// is read-only, the memory it refers to is not: it is assigned, incremented and
// given to atomics through the reference.
#version 450
#extension GL_EXT_buffer_reference : require
layout(local_size_x = 1) in;
layout(buffer_reference, std430) buffer Counts { uint v[]; };
layout(buffer_reference, std430) buffer Totals { uint sum; Counts next; };
layout(push_constant) uniform PC { Counts ptr; Totals totals; } pc;
layout(std140, set = 0, binding = 0) uniform U { Counts ptr; } u;
void main() {
    pc.ptr.v[0] = 1u;
    u.ptr.v[1] = pc.ptr.v[0];
    pc.totals.sum += 2u;
    pc.totals.next.v[3]++;
    atomicAdd(pc.ptr.v[2], 1u);
}
