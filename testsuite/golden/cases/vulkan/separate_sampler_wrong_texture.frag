// RAW
// ARGS: -V -o /dev/null
// A combined sampler takes the texture of its own dimension.
#version 450
layout(set = 0, binding = 0) uniform textureCube sky;
layout(set = 0, binding = 1) uniform sampler linearSampler;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = texture(sampler2D(sky, linearSampler), uv);
}
