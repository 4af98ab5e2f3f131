// Issue 46, class 2: `{}` initializes a whole variable, never an element of a
// list (glslang: "wrong number of structure members"), and cannot size an
// unsized array (glslang: "null initializers can't size unsized arrays").
#version 450
#extension GL_EXT_null_initializer : require
layout(location = 0) out vec4 color;
struct Cmd { uint count; vec2 dir; };
void main() {
    Cmd pair[2] = { {}, {} };
    int sizes[] = {};
    color = vec4(pair[0].dir, 0.0, 1.0);
}
