// ARGS: -d
// Desktop 1.10 has no precision qualifiers. glslangValidator -d 12:
//   ERROR: 0:4: '' :  syntax error, unexpected IDENTIFIER
// (exit 2); without -d (ES 1.00) the shader is accepted (es_default_without_version.frag).
precision mediump float;
void main() {
    gl_FragColor = vec4(0.5);
}
