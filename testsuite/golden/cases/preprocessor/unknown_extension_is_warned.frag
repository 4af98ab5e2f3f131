#version 460
// A misspelt extension (GL_EXT_ray_tracing) turns nothing on: glslangValidator
// warns, and refuses it with require; one glslang knows gets no warning.
#extension GL_EXT_raytracing : enable
#extension GL_KHR_shader_subgroup_basic : enable
out vec4 c;
void main() { c = vec4(1.0); }
