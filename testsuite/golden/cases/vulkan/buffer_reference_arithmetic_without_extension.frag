// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// Arithmetic on a reference and indexing one are GL_EXT_buffer_reference2's:
// with GL_EXT_buffer_reference alone they are errors; a reference plus a
// float, or two references added, is no arithmetic at all.
#version 450
#extension GL_EXT_buffer_reference : require
layout(buffer_reference) buffer Node { int x; };
layout(push_constant) uniform Push { Node nodes; };
layout(location = 0) out vec4 color;
void main() {
  Node a = nodes + 1;
  int b = nodes[2].x;
  Node c = nodes + 1.0;
  Node d = nodes + nodes;
  color = vec4(float(b));
}
