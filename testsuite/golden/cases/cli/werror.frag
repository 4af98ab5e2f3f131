// ARGS: --strict -Werror
#version 330 core
uniform float gain;
out vec4 c;
void main() { c = vec4(gain); }
