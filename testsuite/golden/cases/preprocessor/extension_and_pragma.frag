#version 330 core
#extension GL_ARB_separate_shader_objects : enable
#pragma optimize(off)
out vec4 c;
void main() { c = vec4(1.0); }
