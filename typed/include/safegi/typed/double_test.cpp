// The double representation (SAFEGI_DOUBLE=1): the same headers hold doubles in
// every kind, checked or not, and keep the digits float would lose.
#include <gtest/gtest.h>

#include <safegi/typed.hpp>

#if !SAFEGI_DOUBLE
#error "double_test.cpp must be built with SAFEGI_DOUBLE=1 (link SafeGI::typed_double)"
#endif

namespace {
namespace sg = safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);

static_assert(std::is_same_v<sg::real, double>);
static_assert(std::is_same_v<sg::rep_of<sg::quantity<sg::dim::length>>, double>);
static_assert(std::is_same_v<decltype(sg::raw(sg::point<world>{})), glm::dvec3>);
static_assert(std::is_same_v<decltype(sg::raw(sg::spectrum<sg::dim::radiance>{})), glm::dvec3>);
static_assert(std::is_same_v<decltype(sg::raw(sg::map<object, world>{}).forward), glm::dmat4>);
static_assert(std::is_same_v<decltype(sg::dot(sg::normal<world>{}, sg::direction<world>{})), sg::quantity<sg::dim::proj>>);
#if SAFEGI_UNCHECKED
static_assert(std::is_same_v<sg::quantity<sg::dim::radiance>, double>);
#else
static_assert(sg::is_checked);
#endif

TEST(Double, PointsKeepDigitsFloatLoses) {
  // 1e8 m + 1 m: float's spacing at 1e8 is 8 m, double's 1.5e-8 m.
  const sg::point<world> far(sg::real(1e8) * sg::units::metre, sg::zero, sg::zero);
  const sg::vector<world> one(sg::real(1) * sg::units::metre, sg::zero, sg::zero);
  EXPECT_EQ(sg::raw(sg::distance(far + one, far)), 1.0);
  const auto moved = sg::map<world, object>::translation(sg::vector<object>(sg::real(1e8) * sg::units::metre, sg::zero, sg::zero));
  EXPECT_EQ(sg::raw(moved(sg::point<world>(sg::real(0.5) * sg::units::metre, sg::zero, sg::zero)).x()), 1e8 + 0.5);
}

TEST(Double, SpectraAndUnitsInDouble) {
  const sg::spectrum<sg::dim::radiance> L(sg::real(1e-30) * sg::units::radiance_unit);
  const sg::spectrum<sg::dim::radiance> sum = L + sg::spectrum<sg::dim::radiance>(sg::real(1) * sg::units::radiance_unit);
  EXPECT_EQ(sg::raw(sum).r, 1.0 + 1e-30);  // rounds to 1 in float and in double alike
  EXPECT_EQ(sg::raw(sg::real(3) * sg::units::millimetre), 0.003);
  EXPECT_DOUBLE_EQ(sg::pi, 3.14159265358979323846);
}

TEST(Double, NumericLimitsAreDoubles) {
  using length = sg::quantity<sg::dim::length>;
  static_assert(std::is_same_v<decltype(std::numeric_limits<length>::infinity()), length>);
  EXPECT_EQ(sg::raw(std::numeric_limits<length>::max()), std::numeric_limits<double>::max());
  EXPECT_EQ(sg::raw(std::numeric_limits<length>::epsilon()), std::numeric_limits<double>::epsilon());
  EXPECT_TRUE(sg::isinf(std::numeric_limits<length>::infinity()));
  EXPECT_TRUE(sg::isnan(std::numeric_limits<sg::quantity<sg::dim::radiance>>::quiet_NaN()));
}

}  // namespace
