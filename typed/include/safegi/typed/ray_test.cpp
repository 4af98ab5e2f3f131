#include "safegi/typed/ray.hpp"

#include <gtest/gtest.h>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);

static_assert(std::is_trivially_copyable_v<ray<world>>);
static_assert(sizeof(ray<world>) == 2 * sizeof(glm::vec3));

TEST(Ray, PointAtDistance) {
  const ray<world> r{from_raw<point<world>>(glm::vec3(1, 0, 0)), direction<world>(0, 1, 0)};
  EXPECT_EQ(raw(r(2.0f * units::metre)), glm::vec3(1, 2, 0));
  EXPECT_EQ(raw(r(500.0f * units::millimetre)), glm::vec3(1, 0.5f, 0));
}

TEST(Ray, TransformsIntoAnotherSpace) {
  const auto objectFromWorld = map<world, object>::scaling(2, 2, 2);
  const ray<world> r{from_raw<point<world>>(glm::vec3(1, 0, 0)), direction<world>(0, 1, 0)};
  const ray<object> ro = transform(objectFromWorld, r);
  EXPECT_EQ(raw(ro.o), glm::vec3(2, 0, 0));
  EXPECT_EQ(raw(ro.d), glm::vec3(0, 1, 0));
}
}  // namespace
