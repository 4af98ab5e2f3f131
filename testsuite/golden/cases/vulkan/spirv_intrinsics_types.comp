// ARGS: --target-env vulkan1.2
// SYMBOLS
// GL_EXT_spirv_intrinsics (issue 46): spirv_type as a type specifier: a uniform,
// locals and arrays of them, parameters of user functions and of instructions.
// Two spirv_types are one type when their arguments are the same (here through
// one macro and through the same words written out). spirv_decorate_id and
// spirv_execution_mode_id take constants.
#version 460
#extension GL_EXT_spirv_intrinsics : require
#define rayQueryEXT spirv_type(extensions = ["SPV_KHR_ray_query"], capabilities = [4472], id = 4472)
#define accelerationStructureEXT spirv_type(extensions = ["SPV_KHR_ray_query"], capabilities = [4472], id = 5341)
#define EmptyStruct spirv_type(id = 30)

layout(local_size_x = 1) in;
const int size = 9;

spirv_instruction(extensions = ["SPV_KHR_ray_query"], capabilities = [4472, 4478], id = 4473)
void rayQueryInitializeEXT(spirv_by_reference rayQueryEXT rayQuery, accelerationStructureEXT topLevel, uint rayFlags,
                           uint cullMask, vec3 origin, float tMin, vec3 direction, float tMax);
spirv_instruction(extensions = ["SPV_KHR_ray_query"], capabilities = [4478], id = 4474)
void rayQueryTerminateEXT(spirv_by_reference spirv_type(extensions = ["SPV_KHR_ray_query"], capabilities = [4472], id = 4472) rayQuery);

layout(binding = 0) uniform accelerationStructureEXT as;

layout(binding = 1) uniform Counter { uint counter; } x;
spirv_decorate_id(46, size) float aligned;  // AlignmentId (of a constant)
spirv_execution_mode_id(38, size, 1, 1);      // LocalSizeId

void take(EmptyStruct e) {}

void main() {
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, as, 0u, 0xFFu, vec3(0.0), 0.0, vec3(1.0), 1.0);
  rayQueryTerminateEXT(rq);
  EmptyStruct dummy[size];
  take(dummy[1]);
}
