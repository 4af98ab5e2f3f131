#version 450
// runtime_vk's test shader for sampled textures: reads an environment map of
// radiance texel by texel (texelFetch) and between texels (bilinear).
#include <safegi/prelude.sgl>

layout(local_size_x = 1) in;
layout(set = 0, binding = 0) uniform sampler2D<spectrum<radiance>> environment;
layout(set = 0, binding = 1, std430) writeonly buffer Texels { spectrum<radiance> texels[]; } fetched;
layout(set = 0, binding = 2, std430) writeonly buffer Between { spectrum<radiance> between[]; } filtered;

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    fetched.texels[i] = texelFetch(environment, ivec2(i, 0), 0).rgb;
    // Halfway between texel i and i + 1 of the first row (4x2 texture).
    const vec2 uv = vec2((float(i) + 1.0) / 4.0, 0.25);
    filtered.between[i] = textureLod(environment, uv, 0.0).rgb;
}
