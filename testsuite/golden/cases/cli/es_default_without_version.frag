// No #version: ES 1.00, as glslangValidator assumes (its default unless -d);
// glslangValidator 12 accepts this shader too (exit 0). The emitted GLSL
// states the version it was checked as.
precision mediump float;
varying vec2 uv;
uniform sampler2D tex;
void main() {
    mediump float x = 0.5;
    gl_FragColor = texture2D(tex, uv) * x;
}
