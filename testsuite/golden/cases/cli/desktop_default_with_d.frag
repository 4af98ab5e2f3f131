// ARGS: -d
// -d: no #version means desktop GLSL 1.10, as with glslangValidator -d (exit 0
// there too). #line 0: before 3.30 `#line N` makes the next line N + 1.
varying vec3 n;
void main() {
    gl_FragColor = vec4(normalize(n), 1.0);
}
