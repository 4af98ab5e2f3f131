// RAW
// ARGS: --target-env vulkan2.0
#version 450
void main() {}
