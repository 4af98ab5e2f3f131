#version 450
// runtime_vk's test shader: scales a buffer of radiance by a push-constant
// factor, adds a tint from a uniform block, writes the result to a buffer and
// to an image. The workgroup width and an exposure are specialization constants.
#include <safegi/prelude.sgl>

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const float exposure = 1.0;
layout(constant_id = 2) const uint row_length = 4u;

layout(set = 0, binding = 0, std430) readonly buffer Input { spectrum<radiance> values[]; } source;
layout(set = 0, binding = 1, std430) writeonly buffer Output { spectrum<radiance> scaled[]; } target;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D image;
layout(set = 1, binding = 0) uniform Params {
    spectrum<radiance> tint;
    float<1> weights[2];
} params;
layout(push_constant) uniform Push {
    float<1> factor;
    uint count;
} push;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    const spectrum<radiance> L = (source.values[i] * push.factor + params.tint * params.weights[1]) * exposure;
    target.scaled[i] = L;
    imageStore(image, ivec2(int(i % row_length), int(i / row_length)), vec4(L, 1.0));
}
