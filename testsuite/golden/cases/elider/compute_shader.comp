#version 430
#include <safegi/prelude.sgl>
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Data { float<length> d[]; } data;
void main() { data.d[gl_GlobalInvocationID.x] *= 2.0; }
