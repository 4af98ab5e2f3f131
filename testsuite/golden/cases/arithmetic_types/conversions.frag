// Implicit conversions widen (glslang's rules with explicit types); literal suffixes give the
// type; built-ins take every width; a mixed operation meets at the wider type.
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
layout(location = 0) out vec4 o;
void main() {
  int16_t c = 1s;
  uint8_t u = uint8_t(2);
  uint16_t us = 7us;
  int i = u;                    // uint8_t -> int
  uint r = i + u;               // int + uint8_t is uint
  int64_t q = c * 2l + i;       // int16_t and int -> int64_t
  uint64_t a = 3ul + us;
  float16_t h = 2.0hf * float16_t(c) + c;
  f16vec3 v = f16vec3(h);
  i16vec3 e;
  v = frexp(v, e);
  double dd = 1.0lf + q;        // int64_t -> double
  o = vec4(r, q, h, dd);
  o.x = sin(h) + max(h, 1.0hf) + float(clamp(q, 0l, 3l)) + abs(c) + min(u, uint8_t(3)) + length(v) + float(a);
}
