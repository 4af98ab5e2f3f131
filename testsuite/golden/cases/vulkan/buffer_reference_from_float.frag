// RAW
// ARGS: -V -o /dev/null
// A reference is made from an address, not from a float.
#version 460
#extension GL_EXT_buffer_reference : require
layout(buffer_reference, std430) buffer Node { float value; };
layout(location = 0) out vec4 color;
void main() {
    Node n = Node(1.0);
    color = vec4(n.value);
}
