// ARGS: --target-env vulkan1.2
// A radiance stored as f16vec3 keeps its dimension both ways.
#version 450
#extension GL_EXT_shader_explicit_arithmetic_types : require
#include <safegi/prelude.sgl>
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Radiance { f16vec3<radiance> L16[]; };
layout(std430, binding = 1) buffer Depth { float16_t<length> d16; };
layout(push_constant) uniform Light { spectrum<radiance> Lin; spectrum<irradiance> E; float<length> d; };
void main() {
  L16[0] = f16vec3(Lin);                  // fine: radiance stored at half precision
  spectrum<radiance> back = vec3(L16[1]); // fine: and read back
  spectrum<radiance> sum = L16[2] + Lin;  // fine: widened implicitly
  float<length> twice = d16 * 2.0hf;      // fine
  L16[3] = f16vec3(E);                    // irradiance is not radiance
  spectrum<radiance> s = vec3(L16[4]) * d;
  L16[5] = f16vec3<radiance>(d);
}
