// RAW
// ARGS: -V -o /dev/null
// Issue 46, class 1: the attributes of GL_EXT_control_flow_attributes reach
// glslang's SPIR-V (loop and selection controls) through the plain GLSL.
#version 450
#extension GL_EXT_control_flow_attributes : require
layout(location = 0) in float x;
layout(location = 0) out vec4 color;
void main() {
    float s = 0.0;
    [[unroll]] for (int i = 0; i < 4; ++i) s += x;
    [[dont_unroll]] while (s > 10.0) s -= 1.0;
    [[flatten]] if (x > 0.5) s += 1.0;
    [[branch]] switch (int(x)) { case 0: s += 2.0; break; default: break; }
    color = vec4(s);
}
