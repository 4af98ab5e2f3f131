// `packed` is a reserved word only before GLSL 3.30 (glslang); from there a
// name like any other. Issue 19, false-positive class 5.
#version 460
layout(location = 0) out vec4 color;
void main() {
    uint packed = packUnorm4x8(vec4(0.5));
    color = unpackUnorm4x8(packed);
}
