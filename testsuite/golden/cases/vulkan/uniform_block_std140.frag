// RAW
// ARGS: -V -o /dev/null
// A uniform block is std140 in Vulkan GLSL: `float a[2]` strides 16 bytes and
// ends at byte 32, so an offset of 8 for the next member overlaps it.
#version 450
layout(set = 0, binding = 0) uniform Material {
    layout(offset = 0) float a[2];
    layout(offset = 8) float b;
} mat;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(mat.a[1] * mat.b);
}
