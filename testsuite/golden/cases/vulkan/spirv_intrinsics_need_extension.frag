// RAW
// ARGS: -o /dev/null
// Without `#extension GL_EXT_spirv_intrinsics`, each of its forms is an error
// that names the extension (the words stay names a program may use: a
// function called spirv_literal is fine). (String literals and `GL_` macros
// stay errors of the preprocessor: preprocessor/ cases.)
#version 450
spirv_execution_mode(5027);
spirv_decorate(0) float a = 1.0;
spirv_decorate_id(5634, a) float b = 1.0;
layout(location = 0) spirv_storage_class(5338) vec4 payload;
spirv_type(id = 30) d;
spirv_instruction(id = 61) vec4 load(spirv_by_reference vec4 pointer, spirv_literal int memoryOperands);
float spirv_literal(float x) { return x; }
layout(location = 0) out vec4 color;
void main() {
  color = vec4(spirv_literal(1.0));
}
