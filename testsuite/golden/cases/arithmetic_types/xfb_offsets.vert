// Transform feedback of 16- and 64-bit values: 2 and 8 bytes a component, and offsets to match.
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
layout(xfb_buffer = 0, xfb_stride = 6) out;
layout(xfb_offset = 0) out f16vec3 packed_half;
layout(xfb_buffer = 1, xfb_offset = 4) out int64_t misaligned;
void main() {
  packed_half = f16vec3(1.0hf);
  misaligned = 1l;
  gl_Position = vec4(0.0);
}
