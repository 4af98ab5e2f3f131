// RAW
// ARGS: -V -o /dev/null
// Issue 46 (class 5, found by the glslang Test/ corpus): nonuniformEXT is also a
// qualifier, of locals, parameters and return types (GL_EXT_nonuniform_qualifier).
#version 450
#extension GL_EXT_nonuniform_qualifier : require
layout(set = 0, binding = 0) uniform sampler2D maps[];
layout(location = 0) flat in int which;
layout(location = 0) out vec4 color;
nonuniformEXT int pick(nonuniformEXT int i) { return i + 1; }
void main() {
    nonuniformEXT int slot = pick(which);
    color = texture(maps[slot], vec2(0.5));
}
