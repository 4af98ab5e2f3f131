// ARGS: --glsl-version 450
// --glsl-version checks the shader as 4.50 whatever #version says, and the
// emitted #version says 450 (the profile kept): layout(binding) needs 4.20.
// glslangValidator 12 applies --glsl-version only when it writes SPIR-V
// (`glslangValidator -G --aml --amb --glsl-version 450` accepts this shader,
// exit 0; without -G it checks as 3.30: "ERROR: 0:8: 'binding' : not supported
// for this version or the enabled extensions").
#version 330 core
layout(binding = 0) uniform sampler2D tex;
in vec2 uv;
out vec4 color;
void main() {
    color = texture(tex, uv);
}
