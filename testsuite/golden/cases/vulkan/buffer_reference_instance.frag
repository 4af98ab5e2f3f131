// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// A buffer_reference block with an instance name (glslang's
// spv.bufferhandle6.frag): the block's name is the reference type, and the
// instance a storage buffer of its members at the block's set and binding.
#version 450
#extension GL_EXT_buffer_reference : require
layout(buffer_reference) buffer Node;
layout(set = 1, binding = 2, buffer_reference) buffer Node {
  int value;
  Node next;
} head;
layout(location = 0) out vec4 color;
void main() {
  int sum = head.value + head.next.value + head.next.next.value;
  head.next.value = sum;
  color = vec4(float(sum));
}
