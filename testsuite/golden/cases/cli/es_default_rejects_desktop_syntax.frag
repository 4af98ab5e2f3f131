// No #version: ES 1.00, where global `out` does not exist. glslangValidator 12:
//   ERROR: 0:4: 'out for stage outputs' : not supported for this version or the enabled extensions
// and three more (exit 2); with -d (desktop 1.10) the same first error
// (desktop_default_rejects_out.frag).
out vec4 color;
void main() {
    color = vec4(1.0);
}
