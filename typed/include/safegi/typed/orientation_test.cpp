#include "safegi/typed/orientation.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);

// Differences with the shaded point are oriented; -x flips; normalize and sums of one
// orientation keep it; everything else sees the plain value.
static_assert(std::is_same_v<decltype(point<world>{} - shaded(point<world>{})), oriented<away, vector<world>>>);
static_assert(std::is_same_v<decltype(shaded(point<world>{}) - point<world>{}), oriented<toward, vector<world>>>);
static_assert(std::is_same_v<decltype(shaded(point<world>{}) - shaded(point<world>{})), vector<world>>);
static_assert(std::is_same_v<decltype(-as_away(direction<world>{})), oriented<toward, direction<world>>>);
static_assert(std::is_same_v<decltype(normalize(as_toward(vector<world>{}))), oriented<toward, direction<world>>>);
static_assert(std::is_same_v<decltype(as_away(direction<world>{}) + as_away(direction<world>{})),
                             oriented<away, vector<world, dim::dimensionless>>>);
static_assert(std::is_same_v<decltype(as_away(direction<world>{}) + as_toward(direction<world>{})),
                             vector<world, dim::dimensionless>>);
static_assert(std::is_same_v<decltype(dot(normal<world>{}, as_away(direction<world>{}))), quantity<dim::proj>>);
// Free: the same bytes as the value.
static_assert(sizeof(oriented<away, direction<world>>) == sizeof(direction<world>));
static_assert(std::is_trivially_copyable_v<oriented<away, vector<world>>>);
// A parameter that asks for one orientation takes only that one.
static_assert(std::is_convertible_v<oriented<away, direction<world>>, direction<world>>);

// A light's emission seen from a lens, in the convention of pbrt's Light::Li: the light is
// handed the direction from the lens to the light (away from the shaded point, the lens).
// This is the interface a real bug got wrong: it was given the light's travel direction.
float facing(oriented<away, direction<world>> lens_to_light, normal<world> light_normal) {
  // The light emits toward the lens when its normal faces back along lens_to_light.
  return -raw(dot(light_normal, lens_to_light));
}

TEST(Orientation, DifferencesWithTheShadedPointAreOriented) {
  const point<world> light_pos(0.0f * units::metre, 0.0f * units::metre, 2.0f * units::metre);
  const shaded_point<world> lens = shaded(point<world>(0.0f * units::metre, 0.0f * units::metre, 0.0f * units::metre));
  const oriented<away, vector<world>> to_light = light_pos - lens;
  const oriented<toward, vector<world>> travel = lens - light_pos;
  EXPECT_EQ(raw(to_light), glm::vec3(0, 0, 2));
  EXPECT_EQ(raw(travel), glm::vec3(0, 0, -2));
  const oriented<away, direction<world>> wi = normalize(to_light);
  EXPECT_EQ(raw(wi), glm::vec3(0, 0, 1));
  const normal<world> down(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(facing(wi, down), 1.0f);
  EXPECT_EQ(facing(-normalize(travel), down), 1.0f);  // the travel direction, flipped
  EXPECT_EQ(facing(as_away(direction<world>(0, 0, 1)), down), 1.0f);
  // Forgetting the orientation is free: a plain direction takes it.
  const direction<world> plain = wi;
  EXPECT_EQ(raw(plain), raw(wi));
  EXPECT_EQ(raw(unoriented(travel)), glm::vec3(0, 0, -2));
  // The shaded point is a point everywhere else.
  EXPECT_EQ(raw(distance(light_pos, lens)), 2.0f);
  EXPECT_EQ(raw(from_raw<oriented<away, direction<world>>>(glm::vec3(1, 0, 0))), glm::vec3(1, 0, 0));
}
}  // namespace
