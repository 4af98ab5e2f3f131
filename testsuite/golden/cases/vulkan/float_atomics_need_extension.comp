// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// Atomics on floating-point values need their extension, as glslang says:
// add, exchange, load and store of float and double GL_EXT_shader_atomic_float;
// min and max, and anything on float16_t, GL_EXT_shader_atomic_float2; the
// forms with scope and semantics GL_KHR_memory_scope_semantics. An integer
// atomic needs none; a float image's imageAtomicExchange is GLSL 4.50's own.
#version 450
#extension GL_EXT_shader_atomic_float : require
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
layout(local_size_x = 1) in;
layout(binding = 0, r32f) uniform image2D img;
shared float f;
shared float16_t h;
shared uint u;
void main() {
  atomicAdd(f, 1.0);                        // fine: GL_EXT_shader_atomic_float
  atomicAdd(u, 1u);                         // fine
  imageAtomicExchange(img, ivec2(0), 1.0);  // fine
  imageAtomicAdd(img, ivec2(0), 1.0);       // fine
  atomicMin(f, 1.0);                        // needs GL_EXT_shader_atomic_float2
  atomicAdd(h, float16_t(1.0));             // needs GL_EXT_shader_atomic_float2
  imageAtomicMax(img, ivec2(0), 1.0);       // needs GL_EXT_shader_atomic_float2
  atomicAdd(f, 1.0, 1, 0, 0);               // needs GL_KHR_memory_scope_semantics
  imageAtomicAnd(img, ivec2(0), 1.0);       // no float And
}
