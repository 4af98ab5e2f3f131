// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// GL_EXT_buffer_reference2: a reference plus or minus an integer, indexed
// (r[i] is r + i), or the difference of two (an int64_t); a reference made
// from a constant address is a constant, so glslang's `sizeof` idiom, the
// address of T(0) + 1, sizes an array (the block's 8 bytes rounded up to its
// buffer_reference_align: 8).
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference2 : require
layout(buffer_reference, buffer_reference_align = 8) buffer Node { int x; float y; };
#define sizeof(T) (uint64_t(T(uint64_t(0)) + 1))
float scratch[int(sizeof(Node))];
const int three = int(uint64_t(Node(uint64_t(3))));
int other[three];
layout(push_constant) uniform Push { Node nodes; };
layout(location = 0) out vec4 color;
void main() {
  Node n = nodes + 2;
  n += 1;
  n = 1 + n - 2;
  n[3].x = 4;
  int64_t apart = n - nodes;
  scratch[7] = other.length() + scratch.length();
  color = vec4(n.y, nodes[int(apart)].y, 0.0, 1.0);
}
