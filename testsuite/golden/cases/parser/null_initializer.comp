// Issue 46, class 2: GL_EXT_null_initializer. `= {}` gives every member of a
// struct, vector, scalar or sized array its zero, for locals, globals and
// shared variables; the plain GLSL keeps it.
#version 450
#extension GL_EXT_null_initializer : require
layout(local_size_x = 1) in;
struct Cmd { uint count; vec2 dir; };
layout(std430, binding = 0) buffer Out { Cmd cmds[]; };
Cmd first = {};
shared Cmd pending = {};
void main() {
    Cmd c = {};
    float f = {};
    vec3 v = {};
    const Cmd none = {};  // (glslang 12 crashes on reading a member of it: none.count)
    Cmd batch[2] = {};
    c.count = 3u + batch[1].count + first.count + pending.count;
    cmds[0] = c;
    cmds[1].dir = vec2(f) + v.xy;
}
