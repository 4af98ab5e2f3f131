// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// GL_KHR_memory_scope_semantics (the Vulkan memory model): the coherence
// qualifiers devicecoherent, queuefamilycoherent, workgroupcoherent,
// subgroupcoherent and nonprivate on images, buffers, their members and a
// reference; the gl_Scope*, gl_StorageSemantics* and gl_Semantics* constants;
// atomicLoad, atomicStore and the atomics with scope and semantics (64-bit
// ones too); imageAtomicLoad/Store; memoryBarrier(scope, storage, semantics)
// and controlBarrier.
#version 450
#extension GL_KHR_memory_scope_semantics : require
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_EXT_buffer_reference : require
#pragma use_vulkan_memory_model
layout(local_size_x = 64) in;
layout(buffer_reference) buffer Payload { uint x[]; };
layout(binding = 0, r32ui) workgroupcoherent uniform uimage2D counts;
layout(binding = 1, r32i) devicecoherent uniform iimage2D signed_counts;
layout(binding = 2) buffer Flags { queuefamilycoherent uint ready; subgroupcoherent uint lanes; } flags;
layout(binding = 3) nonprivate uniform sampler2D tex;
layout(push_constant) uniform Push { Payload payload; };
shared uint total;
shared uint64_t wide;
const int relaxed = gl_SemanticsRelaxed;  // a constant expression
void main() {
  nonprivate Payload p = payload;
  uint before = atomicAdd(total, 1u, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsRelaxed);
  uint seen = atomicLoad(flags.ready, gl_ScopeDevice, gl_StorageSemanticsBuffer, gl_SemanticsAcquire | gl_SemanticsMakeVisible);
  atomicStore(p.x[0], seen, gl_ScopeQueueFamily, gl_StorageSemanticsBuffer, gl_SemanticsRelease | gl_SemanticsMakeAvailable);
  atomicCompSwap(total, 0u, before, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsAcquire, gl_StorageSemanticsShared, relaxed);
  atomicMax(wide, uint64_t(7), gl_ScopeDevice, 0, 0);
  uint c = imageAtomicLoad(counts, ivec2(0), gl_ScopeWorkgroup, gl_StorageSemanticsImage, gl_SemanticsAcquire);
  imageAtomicStore(signed_counts, ivec2(0), int(c), gl_ScopeDevice, gl_StorageSemanticsImage, gl_SemanticsRelease);
  imageAtomicAdd(counts, ivec2(1), 1u, gl_ScopeDevice, gl_StorageSemanticsImage, gl_SemanticsRelaxed);
  controlBarrier(gl_ScopeWorkgroup, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsAcquireRelease);
  memoryBarrier(gl_ScopeDevice, gl_StorageSemanticsBuffer | gl_StorageSemanticsImage, gl_SemanticsAcquireRelease);
  flags.lanes = uint(texture(tex, vec2(0.5)).x);
}
