// RAW
// ARGS: -V --symbols - -o /dev/null
// Targeting Vulkan, glslang places a member at its explicit offset without
// checking the order (SPIR-V forbids only overlaps), so members may be
// declared out of order; their offsets and the block's size (the end of its
// last byte, 60 for b2) go into the table. The order is still GLSL's rule
// for OpenGL (`layout 'offset' … lies inside the member before it`).
#version 450
layout(set = 0, binding = 0, std140) uniform b1 {
    layout(offset = 8)  int a;
    layout(offset = 4)  int b;
    layout(offset = 0)  int c;
    layout(offset = 12) int d;
} i1;
layout(set = 0, binding = 1, std430) buffer b2 {
    layout(offset = 32) vec3 e;
                        vec3 f;
    layout(offset = 16) vec3 g;
    layout(offset = 0)  vec3 h;
} i2;
void main() { i2.h = vec3(i1.a + i1.b + i1.c + i1.d); }
