// RAW
// ARGS: -V -o /dev/null
// The work group size from specialization constants: gl_WorkGroupSize is a
// constant expression (an array size), taken from local_size_x_id.
#version 450
layout(local_size_x_id = 0, local_size_y = 4) in;
layout(constant_id = 1) const uint kScale = 2u;
layout(set = 0, binding = 0, std430) buffer Data { float values[]; };
shared float tile[gl_WorkGroupSize.x * gl_WorkGroupSize.y];
void main() {
    tile[gl_LocalInvocationIndex] = values[gl_GlobalInvocationID.x] * float(kScale);
    barrier();
    values[gl_GlobalInvocationID.x] = tile[0];
}
