// RAW
// ARGS: -V -o /dev/null
// In Vulkan GLSL a push-constant block is std430 and a uniform block std140 by
// default (GL_KHR_vulkan_glsl), so explicit offsets are checked by those rules:
// `float a[2]` takes 8 bytes in std430, so `b` may start at 8. Issue 19, class 3.
#version 450
layout(push_constant) uniform PC {
    layout(offset = 16) float roughness;
    layout(offset = 20) float a[2];
    layout(offset = 28) float b;
} pc;
layout(set = 0, binding = 0) uniform Material { layout(offset = 0) vec4 albedo; layout(offset = 16) float metal; } mat;
layout(location = 0) out vec4 color;
void main() {
    color = mat.albedo * pc.roughness * mat.metal * pc.a[1] * pc.b;
}
