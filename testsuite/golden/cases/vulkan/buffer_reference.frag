// RAW
// ARGS: -V -o /dev/null
// GL_EXT_buffer_reference: a buffer_reference block's name is a type, declared
// ahead (`buffer Node;`) or by its block, usable inside itself; made from a
// uvec2 (GL_EXT_buffer_reference_uvec2). Issue 19, false-positive class 1.
#version 460
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
#extension GL_EXT_scalar_block_layout : require
layout(buffer_reference) buffer Node;
layout(buffer_reference, scalar, buffer_reference_align = 4) buffer Vertices { vec3 v[]; };
layout(buffer_reference, std430) buffer Node { Node next; float value; };
layout(push_constant) uniform PC { uvec2 vertices; Node head; } pc;
layout(location = 0) out vec4 color;
void main() {
    Vertices verts = Vertices(pc.vertices);
    Node n = pc.head;
    color = vec4(verts.v[0] + vec3(n.next.value), 1.0);
}
