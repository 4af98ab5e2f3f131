// Issue 46, class 1: without '#extension GL_EXT_control_flow_attributes' an
// attribute is an error (glslang: "required extension not requested"); each
// is reported and the statement after it is still checked.
#version 450
layout(location = 0) out vec4 color;
void main() {
    float s = 0.0;
    [[unroll]] for (int i = 0; i < 4; ++i) s += 1.0;
    [[flatten]] if (s > 2.0) s = 2.0;
    color = vec4(s);
}
