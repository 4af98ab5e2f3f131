#version 420 core
// Issue 46, class 6: at 4.20 layout(offset) belongs to atomic counters only; a
// uniform block member's offset needs 4.40 or GL_ARB_enhanced_layouts.
layout(binding = 0, offset = 0) uniform atomic_uint hits;
layout(std140, binding = 1) uniform Params { layout(offset = 16) vec4 tint; };
out vec4 color;
void main() { color = tint * float(atomicCounter(hits)); }
