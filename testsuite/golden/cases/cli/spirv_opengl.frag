// RAW
// ARGS: -G -o /dev/null
// -G: SPIR-V for OpenGL. Locations and bindings are auto-mapped (glslangValidator
// needs --aml --amb for this shader: "'c' : non-opaque uniform variables need a
// layout(location=L)"); the module equals glslangValidator -G --aml --amb's of
// the emitted GLSL (ctest spirv.matches_glslangValidator).
#version 330 core
uniform vec4 c;
out vec4 color;
void main() {
    color = c;
}
