// ARGS: --glsl-version 300es
// A shader without #version checked as ES 3.00: the emitted GLSL starts with
// `#version 300 es` (then `#line 1`, so driver messages keep the lines).
precision mediump float;
in vec2 uv;
out vec4 color;
void main() {
    color = vec4(uv, 0.0, 1.0);
}
