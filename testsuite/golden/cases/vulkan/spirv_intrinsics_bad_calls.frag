// RAW
// ARGS: -o /dev/null
// GL_EXT_spirv_intrinsics: an argument of a spirv_by_reference parameter must
// be a variable (a read-only one is fine), one of a spirv_literal parameter a
// constant expression; two spirv_types of different arguments are different
// types. A string literal is no constructor argument (glslang 12 takes one and
// builds a constant of its address: glslang's spv.intrinsicsStringConstructorError.vert).
// spirv_decorate_id names a variable or constant declared before it.
#version 450
#extension GL_EXT_spirv_intrinsics : enable
spirv_instruction(id = 61)
vec4 load(spirv_by_reference vec4 pointer, spirv_literal int memoryOperands);
void take(spirv_type(id = 30) e) {}
layout(location = 0) in vec4 color_in;
layout(location = 0) out vec4 color;
uniform int operands;
const int kVolatile = 0x1;
spirv_decorate_id(46, kAlignment) float aligned;
void main() {
  color = load(color_in, kVolatile);  // fine
  color = load(vec4(1.0), 0);
  color = load(color, operands);
  spirv_type(id = 31) other;
  take(other);
  uint u = uint("foo");
}
