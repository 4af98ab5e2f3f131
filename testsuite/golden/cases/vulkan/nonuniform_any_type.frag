// RAW
// ARGS: -V -o /dev/null
// Issue 46, class 5: nonuniformEXT (GL_EXT_nonuniform_qualifier) takes a value
// of any type and returns it: a sampler built from an indexed texture, an
// index, a vector.
#version 450
#extension GL_EXT_nonuniform_qualifier : require
layout(set = 0, binding = 0) uniform texture2D images[];
layout(set = 0, binding = 1) uniform sampler linear;
layout(set = 0, binding = 2) uniform sampler2D combined[];
layout(set = 0, binding = 3, std430) buffer Data { vec4 d; } data[];
layout(location = 0) flat in int i;
layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = texture(nonuniformEXT(sampler2D(images[i], linear)), uv);
    color += texture(combined[nonuniformEXT(i)], uv);
    color += data[nonuniformEXT(i)].d;
    color.xy += nonuniformEXT(uv);
}
