// RAW
// ARGS: -V -R --amb -o /dev/null
// -R gathers default-block uniforms into one block, which --amb binds
// (glslangValidator -V -R --amb: exit 0 on the emitted GLSL).
#version 450
uniform vec4 c;
layout(location = 0) out vec4 color;
void main() {
    color = c;
}
