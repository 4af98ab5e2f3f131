// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null -o /dev/null
// WITH: vulkan/inputs/tracer.sgl.rgen
// The miss shader receives an irradiance, but the ray generation shader
// traces a radiance (location 0) and a visibility (location 1): a payload of
// the wrong dimension is an error across the pipeline.
#version 460
#extension GL_EXT_ray_tracing : require
#include <safegi/prelude.sgl>
layout(location = 0) rayPayloadInEXT spectrum<irradiance> sky;
void main() {
    sky = spectrum<irradiance>(0.1, 0.2, 0.4);
}
