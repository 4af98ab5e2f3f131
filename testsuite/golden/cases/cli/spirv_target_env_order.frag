// RAW
// ARGS: --target-env spirv1.4 --target-env vulkan1.1 -o /dev/null
// Two --target-env in any order, as glslangValidator takes them (it accepts
// this shader with them, exit 0): Vulkan 1.1 semantics, SPIR-V 1.4.
#version 450
layout(location = 0) out vec4 color;
void main() {
    color = vec4(1.0);
}
