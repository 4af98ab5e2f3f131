#version 460
#extension GL_EXT_ray_tracing : require
// A camera ray that leaves the scene sees black: the area light is the only emitter.
#include <safegi/prelude.sgl>

layout(location = 0) rayPayloadInEXT spectrum<radiance> radiance;

void main() {
    radiance = spectrum<radiance>(0.0);
}
