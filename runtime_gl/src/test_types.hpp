#pragma once
// Stand-ins for typed-library types in tests that must not depend on it:
// three floats that describe themselves as a spectrum of one dimension or a
// point in one space.
#include "safegi/symbol_table/value_traits.hpp"

namespace safegi::gl::testing {

inline const DimensionExponents kRadiance{
    {"energy", 1}, {"length", -2}, {"proj", -1}, {"solid_angle", -1}, {"time", -1}};
inline const DimensionExponents kIrradiance{{"energy", 1}, {"length", -2}, {"time", -1}};

struct radiance_rgb {
  float r, g, b;
  friend bool operator==(const radiance_rgb&, const radiance_rgb&) = default;
};
struct irradiance_rgb {
  float r, g, b;
};
struct unitless_rgb {
  float r, g, b;
};
struct camera_from_world {
  float m[16];
};
struct ndc_point {
  float x, y, z;
};
struct world_point {
  float x, y, z;
};

}  // namespace safegi::gl::testing

namespace safegi::gl {

template <>
struct value_traits<testing::radiance_rgb> : detail::bitwise_traits<testing::radiance_rgb, glm::vec3> {
  static ValueType describe() { return {Kind::spectrum, "vec3", {testing::kRadiance, ""}, {}}; }
};
template <>
struct value_traits<testing::irradiance_rgb> : detail::bitwise_traits<testing::irradiance_rgb, glm::vec3> {
  static ValueType describe() { return {Kind::spectrum, "vec3", {testing::kIrradiance, ""}, {}}; }
};
template <>
struct value_traits<testing::unitless_rgb> : detail::bitwise_traits<testing::unitless_rgb, glm::vec3> {
  static ValueType describe() { return {Kind::spectrum, "vec3", {}, {}}; }
};
template <>
struct value_traits<testing::camera_from_world> : detail::bitwise_traits<testing::camera_from_world, glm::mat4> {
  static ValueType describe() { return {Kind::map, "mat4", {}, {"world", "camera"}}; }
};
template <>
struct value_traits<testing::ndc_point> : detail::bitwise_traits<testing::ndc_point, glm::vec3> {
  static ValueType describe() { return {Kind::point, "vec3", {}, {"ndc"}}; }
};
template <>
struct value_traits<testing::world_point> : detail::bitwise_traits<testing::world_point, glm::vec3> {
  static ValueType describe() { return {Kind::point, "vec3", {}, {"world"}}; }
};

}  // namespace safegi::gl
