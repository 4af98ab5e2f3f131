// RAW
// ARGS: --target-env spirv1.3
// spirv1.x only sets the SPIR-V version; the semantics come from -V, -G,
// --client or a vulkan/opengl --target-env.
#version 450
void main() {}
