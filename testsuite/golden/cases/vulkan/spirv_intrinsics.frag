// ARGS: --target-env vulkan1.2
// SYMBOLS
// GL_EXT_spirv_intrinsics (issue 46): an execution mode, decorations (several
// on one declaration, one through a macro, one of strings), a built-in the
// shader declares itself (`gl_` names are allowed with the extension, and so
// are `GL_` macros and string literals), and instructions without a body,
// whose parameters may be spirv_by_reference (a variable) or spirv_literal (a
// constant). The emitted GLSL keeps every one of them as written.
#version 450
#extension GL_EXT_spirv_intrinsics : enable
#define GL_ARB_shader_stencil_export 1
#define __decorated spirv_decorate(extensions = ["SPV_AMD_shader_explicit_vertex_parameter"], 4999)

spirv_execution_mode(5027); // StencilRefReplacingEXT

spirv_decorate(extensions = ["SPV_EXT_shader_stencil_export"], capabilities = [5013], 11, 5014)
out int gl_FragStencilRef;

spirv_decorate(0)                                                                      // RelaxedPrecision
spirv_decorate_string(extensions = ["SPV_GOOGLE_hlsl_functionality1"], 5635, "foobar")  // UserSemantic
float scale = 1.0;

spirv_instruction(set = "GLSL.std.450", id = 35) // modf
float modf_by_pointer(float x, spirv_by_reference float i);

spirv_instruction(extensions = ["SPV_AMD_shader_explicit_vertex_parameter"], set = "SPV_AMD_shader_explicit_vertex_parameter", id = 1)
float interpolateAtVertexAMD(float interpolant, uint vertexIdx);

spirv_instruction(id = 61)
vec4 load(spirv_by_reference vec4 pointer, spirv_literal int memoryOperands);

layout(location = 0) in __decorated float floatIn;
layout(location = 1) in flat int stencil;
layout(location = 0) out vec4 color;

void main() {
  gl_FragStencilRef = stencil;
  float whole;
  float part = modf_by_pointer(floatIn, whole);
  color = load(color, 0x1) + vec4(part, whole, interpolateAtVertexAMD(floatIn, 1u), scale);
}
