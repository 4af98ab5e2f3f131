#pragma once
// Host types of the test shaders: the typed library's (checked or unchecked
// by the build) and the scene's triangle, a std430 struct.
#include <cstdint>
#include <safegi/typed.hpp>
#include <string_view>

#include "safegi/runtime_vk/layout.hpp"

namespace safegi::vk::testing {

using radiance = spectrum<dim::radiance>;
using world_point = point<spaces::world>;
using world_vector = vector<spaces::world>;
using area = quantity<dim::area>;

inline radiance rgb(float r, float g, float b) { return from_raw<radiance>(glm::vec3(r, g, b)); }
inline world_point at(float x, float y, float z) { return from_raw<world_point>(glm::vec3(x, y, z)); }

// triangles.sgl.comp's `struct Triangle`, std430: vec3s 16-aligned, the uint
// after the last one, 48 bytes in all.
struct Triangle {
  world_point a;
  float pad0 = 0;
  world_point b;
  float pad1 = 0;
  world_point c;
  std::uint32_t material = 0;
};
static_assert(sizeof(Triangle) == 48);

}  // namespace safegi::vk::testing

template <>
struct safegi::vk::std430_struct<safegi::vk::testing::Triangle> {
  static constexpr std::string_view glsl_name = "Triangle";
};
