// Issue 46, class 1: an attribute stands only before a loop, an if or a
// switch (glslang: "syntax error, unexpected LEFT_BRACE").
#version 450
#extension GL_EXT_control_flow_attributes : require
layout(location = 0) out vec4 color;
void main() {
    float s = 0.0;
    [[unroll]] { s += 1.0; }
    color = vec4(s);
}
