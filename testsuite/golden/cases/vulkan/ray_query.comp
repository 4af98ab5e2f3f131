// RAW
// ARGS: -V --target-env vulkan1.2 -o /dev/null
// Ray queries (GL_EXT_ray_query) in a compute shader: a shadow ray.
#version 460
#extension GL_EXT_ray_query : require
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;
layout(set = 0, binding = 1, r32f) uniform image2D visibility;
void main() {
    rayQueryEXT query;
    rayQueryInitializeEXT(query, scene, gl_RayFlagsTerminateOnFirstHitEXT, 0xff, vec3(gl_GlobalInvocationID), 0.001,
                          vec3(0.0, 1.0, 0.0), 100.0);
    while (rayQueryProceedEXT(query)) {}
    const bool hit = rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT;
    imageStore(visibility, ivec2(gl_GlobalInvocationID.xy), vec4(hit ? 0.0 : 1.0));
}
