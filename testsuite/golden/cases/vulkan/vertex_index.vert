// RAW
// ARGS: -V -o /dev/null
// gl_VertexIndex and gl_InstanceIndex are Vulkan's; a specialization constant
// (layout(constant_id)) sizes an array.
#version 450
layout(constant_id = 0) const int kCount = 4;
layout(set = 0, binding = 0) uniform Offsets { vec4 offsets[kCount]; };
void main() {
    gl_Position = offsets[gl_VertexIndex % kCount] + vec4(float(gl_InstanceIndex));
}
