// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// Without GL_KHR_memory_scope_semantics its qualifiers, atomicLoad, the
// 5-argument atomics and the 3-argument memoryBarrier are errors (glslang:
// "required extension not requested"); shadercallcoherent is
// GL_EXT_ray_tracing's.
#version 450
layout(local_size_x = 1) in;
layout(binding = 0) buffer B { uint x; } b;
layout(binding = 1) workgroupcoherent buffer C { uint y; } c;
layout(binding = 2) shadercallcoherent buffer D { uint z; } d;
shared uint s;
void main() {
  uint v = atomicLoad(s, 1, 0, 0);
  atomicAdd(b.x, 1u, 1, 0, 0);
  memoryBarrier(1, 0x40, 0x8);
  atomicAdd(b.x, 1u);  // fine
  memoryBarrier();     // fine
}
