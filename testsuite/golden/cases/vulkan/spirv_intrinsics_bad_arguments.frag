// RAW
// ARGS: -o /dev/null
// GL_EXT_spirv_intrinsics: argument lists glslang's grammar does not take, each
// reported where it goes wrong with what was expected and what was found
// (the declaration is skipped, the next one parsed).
#version 450
#extension GL_EXT_spirv_intrinsics : enable
spirv_decorate(x) float a0 = 1.0;
spirv_decorate(11, 4992, "text") float a1 = 1.0;
spirv_decorate_string(5635) float a2 = 1.0;
spirv_decorate_string(5635, 7) float a3 = 1.0;
spirv_decorate(capability = [1], 0) float a4 = 1.0;
spirv_decorate(0, extensions = ["SPV_X"]) float a5 = 1.0;
spirv_decorate(extensions = [1], 0) float a6 = 1.0;
spirv_execution_mode();
spirv_instruction(set = "GLSL.std.450") float f0(float x);
spirv_instruction(id = 61, 3) float f1(float x);
spirv_type(4472) t0;
spirv_storage_class(5338, 1) vec4 s0;
