// Issue 46, class 1: GL_EXT_control_flow_attributes. Attributes stand before a
// loop, an if or a switch, one or several, with a constant argument or none;
// the plain GLSL keeps them (glslang accepts them there).
#version 450
#extension GL_EXT_control_flow_attributes : require
layout(location = 0) in float x;
layout(location = 0) out vec4 color;
const int kDepth = 4;
void main() {
    float s = 0.0;
    [[unroll]] for (int i = 0; i < 4; ++i) s += x;
    [[dont_unroll]] while (s > 10.0) s -= 1.0;
    [[loop]] do { s *= 0.5; } while (s > 2.0);
    [[flatten]] if (x > 0.5) s += 1.0; else [[branch]] if (x < 0.1) s -= 1.0;
    [[branch]] switch (int(x)) { case 0: s += 2.0; break; default: break; }
    [[unroll, dependency_infinite]] for (int j = 0; j < 2; ++j) s += 1.0;
    [[dependency_length(kDepth)]]
    for (int k = 0; k < 8; ++k) s += 1.0;
    color = vec4(s);
}
