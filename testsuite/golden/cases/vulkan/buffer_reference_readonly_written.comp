// RAW
// ARGS: -V -o /dev/null
// Issue 46, class 4: memory a reference to a readonly buffer_reference block
// refers to stays read-only (glslang 12 does not check it), and so does the
// reference held in a push-constant block.
#version 450
#extension GL_EXT_buffer_reference : require
layout(local_size_x = 1) in;
layout(buffer_reference, std430) buffer Counts { uint v[]; };
layout(buffer_reference, std430) readonly buffer Frozen { uint v[]; };
layout(push_constant) uniform PC { Counts ptr; Frozen frozen; } pc;
void main() {
    pc.frozen.v[0] = 1u;
    pc.ptr = Counts(pc.frozen);
}
