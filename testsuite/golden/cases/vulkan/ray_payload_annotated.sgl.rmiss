// ARGS: -V --target-env vulkan1.2 -o /dev/null
// RAW
// An annotated payload: the miss shader returns the sky's radiance.
#version 460
#extension GL_EXT_ray_tracing : require
#include <safegi/prelude.sgl>
space world;
layout(location = 0) rayPayloadInEXT spectrum<radiance> radiance;
layout(push_constant) uniform Sky { spectrum<radiance> zenith; } sky;
void main() {
    direction<world> d = gl_WorldRayDirectionEXT;
    radiance = sky.zenith * float<1>(0.5 + 0.5 * d.y);
}
