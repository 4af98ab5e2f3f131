#version 420 core
// Issue 46, class 6: an atomic counter's layout(offset) is GLSL 4.20's
// (GL_ARB_shader_atomic_counters); a uniform block member's is 4.40's
// (enhanced layouts), below.
layout(binding = 0, offset = 0) uniform atomic_uint hits;
layout(binding = 0, offset = 4) uniform atomic_uint misses;
layout(binding = 0) uniform atomic_uint total;
out vec4 color;
void main() {
    uint n = atomicCounterIncrement(hits) + atomicCounter(misses) + atomicCounter(total);
    color = vec4(float(n));
}
