// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// A closest-hit shader: the incoming payload, hit attributes, the shader
// record, and the ray and transform built-ins.
#version 460
#extension GL_EXT_ray_tracing : require
layout(location = 0) rayPayloadInEXT vec3 radiance;
hitAttributeEXT vec2 barycentrics;
layout(shaderRecordEXT, std430) buffer Record { vec4 albedo; } record;
void main() {
    const vec3 hit = gl_WorldRayOriginEXT + gl_WorldRayDirectionEXT * gl_HitTEXT;
    const vec3 local = gl_WorldToObjectEXT * vec4(hit, 1.0);
    radiance = record.albedo.rgb * (1.0 - barycentrics.x - barycentrics.y) + local * 0.0 +
               float(gl_PrimitiveID + gl_InstanceCustomIndexEXT) * 0.0;
}
