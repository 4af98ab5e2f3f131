// ARGS: -d
// Desktop 1.10: global `out` needs #version 130. glslangValidator -d 12:
//   ERROR: 0:4: 'out for stage outputs' : not supported for this version or the enabled extensions
out vec4 color;
void main() {
    color = vec4(1.0);
}
