// SYMBOLS
// Members of 8-, 16- and 64-bit types get offsets and sizes in std140 and std430 blocks
// (scalar blocks: compiler.VulkanInterface.ScalarBlocksPackSixteenBitMembers).
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
layout(local_size_x = 1) in;
layout(std140, binding = 0) uniform U { float16_t a; f16vec3 b; int64_t c; u8vec2 d; f16mat2x3 m; int16_t e[3]; } u;
layout(std430, binding = 1) buffer S { uint8_t a; f16vec3 b; uint64_t c; i16vec3 d; f64vec2 e; float16_t f[]; } s;
void main() {
  s.b = u.b + f16vec3(1.0hf);
  s.c = uint64_t(u.c + 3l);
  s.c += 5ul;
  s.d = i16vec3(u.e[0] + 2s);
  s.a = uint8_t(u.d.x);
}
