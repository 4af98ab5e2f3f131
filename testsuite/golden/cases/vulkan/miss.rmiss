// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// A miss shader writes the payload from the ray's direction.
#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec3 radiance;
void main() {
    radiance = vec3(0.5 + 0.5 * gl_WorldRayDirectionEXT.y);
}
