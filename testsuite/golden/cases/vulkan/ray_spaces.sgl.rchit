// ARGS: -V --target-env vulkan1.2 -o /dev/null
// RAW
// The ray built-ins carry the spaces GL_EXT_ray_tracing gives them once the
// program declares `world` and `object`: the world-space hit point is a
// point<world>, and a world-space direction is not an object-space one.
#version 460
#extension GL_EXT_ray_tracing : require
#include <safegi/prelude.sgl>
space world;
space object;
layout(location = 0) rayPayloadInEXT spectrum<radiance> radiance;
void main() {
    point<world> hit = gl_WorldRayOriginEXT + gl_WorldRayDirectionEXT * gl_HitTEXT;
    direction<object> d = gl_WorldRayDirectionEXT;
    radiance = spectrum<radiance>(hit.y + d.y);
}
