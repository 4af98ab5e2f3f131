// RAW
// ARGS: -G -o /dev/null
// glslangValidator -G --aml --amb 12, on the emitted GLSL:
//   ERROR: #version: Desktop shaders for OpenGL SPIR-V require version 330 or higher
#version 150
out vec4 color;
void main() {
    color = vec4(1.0);
}
