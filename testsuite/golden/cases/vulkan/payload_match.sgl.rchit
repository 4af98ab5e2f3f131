// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null -o /dev/null
// WITH: vulkan/inputs/tracer.sgl.rgen
// The closest-hit shader receives the radiance the ray generation shader traces.
#version 460
#extension GL_EXT_ray_tracing : require
#include <safegi/prelude.sgl>
layout(location = 0) rayPayloadInEXT spectrum<radiance> radiance;
void main() {
    radiance = spectrum<radiance>(1.0, 0.5, 0.25);
}
