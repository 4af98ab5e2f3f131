// ARGS: --target-env vulkan1.2
// 64-bit images (GL_EXT_shader_image_int64) and half-float samplers (GL_AMD_gpu_shader_half_float_fetch)
// return texels of their width.
#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_EXT_shader_image_int64 : require
#extension GL_AMD_gpu_shader_half_float : require
#extension GL_AMD_gpu_shader_half_float_fetch : require
layout(set = 0, binding = 0, r64ui) uniform u64image2D counts;
layout(set = 0, binding = 1) uniform f16sampler2D half_tex;
layout(location = 0) out vec4 o;
void main() {
  uint64_t before = imageAtomicAdd(counts, ivec2(0), 1ul);
  u64vec4 texel = imageLoad(counts, ivec2(1));
  f16vec4 h = texture(half_tex, vec2(0.5));
  int64_t wrong = imageLoad(counts, ivec2(2)).x;
  o = vec4(h) + vec4(before + texel.x);
}
