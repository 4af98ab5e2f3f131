// The debug-build check that directions and normals are given unit-length components.
// Built as its own program with NDEBUG undefined (CMakeLists.txt), so the check is on
// whatever the build type.
#include <gtest/gtest.h>

#include "safegi/typed/space.hpp"

namespace sg = safegi;
using sg::spaces::world;

static_assert(SAFEGI_CHECK_UNIT_LENGTH, "this test must be built checked and without NDEBUG");

TEST(UnitLength, UnitComponentsAreAccepted) {
  EXPECT_EQ(sg::direction<world>(0, 0, 1).z(), 1.0f);
  EXPECT_EQ(sg::normal<world>(0.6f, 0.8f, 0).y(), 0.8f);
  // Components rounded to three digits are still a unit vector.
  EXPECT_NEAR(sg::direction<world>(0.577f, 0.577f, 0.577f).x(), 0.577f, 0.0f);
}

TEST(UnitLengthDeathTest, LongDirectionStopsTheProgramNamingIt) {
  EXPECT_DEATH((void)sg::direction<world>(3, 0, 0),
               R"(direction<world>\(3, 0, 0\) is not unit length \(length 3\); build it with normalize\(vector\))");
}

TEST(UnitLengthDeathTest, ZeroNormalStopsTheProgramNamingIt) {
  EXPECT_DEATH((void)sg::normal<world>(0, 0, 0), R"(normal<world>\(0, 0, 0\) is not unit length \(length 0\))");
}

TEST(UnitLengthDeathTest, NanComponentsAreNotUnitLength) {
  EXPECT_DEATH((void)sg::direction<world>(std::nanf(""), 0, 0), "is not unit length");
}

TEST(UnitLength, NormalizeAndRawDataAreNotChecked) {
  // normalize() makes unit vectors; from_raw is the documented way in for trusted data.
  EXPECT_NEAR(sg::raw(sg::normalize(sg::from_raw<sg::vector<world>>(glm::vec3(3, 0, 0)))).x, 1.0f, 1e-6f);
  EXPECT_EQ(sg::raw(sg::from_raw<sg::direction<world>>(glm::vec3(2, 0, 0))).x, 2.0f);
}
