#version 460
#extension GL_EXT_ray_tracing : require
// The shadow ray reached the light sample: it is visible.
#include <safegi/prelude.sgl>

layout(location = 1) rayPayloadInEXT float<1> visibility;

void main() {
    visibility = 1.0;
}
