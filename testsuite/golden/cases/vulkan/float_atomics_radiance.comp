// ARGS: --target-env vulkan1.2
// GL_EXT_shader_atomic_float: a GPU renderer accumulates radiance with atomicAdd.
// The float atomics keep the dimension of what they accumulate: adding an
// irradiance (or a radiance scaled by a length) to a radiance accumulator is
// a dimension error, in shared memory and in a buffer, with and without the
// scope and semantics arguments (GL_KHR_memory_scope_semantics).
#version 450
#extension GL_EXT_shader_atomic_float : require
#extension GL_KHR_memory_scope_semantics : require
#include <safegi/prelude.sgl>
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Film { float<radiance> L[]; };
shared float<radiance> tile;
layout(push_constant) uniform Sample { float<radiance> Li; float<irradiance> E; float<length> d; };
void main() {
  float<radiance> before = atomicAdd(L[gl_LocalInvocationID.x], Li);  // fine
  atomicAdd(tile, Li, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsRelaxed);  // fine
  float<radiance> now = atomicLoad(tile, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsAcquire);  // fine
  atomicStore(L[0], now, gl_ScopeDevice, gl_StorageSemanticsBuffer, gl_SemanticsRelease);  // fine
  atomicAdd(L[1], E);                         // irradiance into a radiance accumulator
  atomicExchange(tile, Li * d, gl_ScopeWorkgroup, gl_StorageSemanticsShared, gl_SemanticsRelaxed);
  float<irradiance> wrong = atomicAdd(L[2], Li);  // the old value is a radiance
}
