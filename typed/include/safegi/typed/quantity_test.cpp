#include "safegi/typed/quantity.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <type_traits>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
using length = quantity<dim::length>;
using area = quantity<dim::area>;
using angle = quantity<dim::angle>;

// Layout proofs: a quantity is exactly its number.
static_assert(sizeof(quantity<dim::radiance>) == sizeof(float));
static_assert(sizeof(quantity<dim::radiance, double>) == sizeof(double));
static_assert(alignof(quantity<dim::length>) == alignof(float));
static_assert(std::is_trivially_copyable_v<quantity<dim::radiance>>);
static_assert(std::is_standard_layout_v<quantity<dim::radiance>>);
// A dimensionless quantity is the plain number.
static_assert(std::is_same_v<quantity<dim::dimensionless>, float>);
static_assert(std::is_same_v<quantity<dim::dimensionless, double>, double>);
static_assert(std::is_same_v<decltype(length{} / length{}), float>);
static_assert(std::is_same_v<decltype(length{} * length{}), area>);
static_assert(std::is_same_v<decltype(1.0f / length{}), quantity<dim::pdf_length>>);
static_assert(std::is_same_v<decltype(safegi::sqrt(area{})), length>);
static_assert(std::is_same_v<decltype(safegi::pow<3>(length{})), quantity<dim::volume>>);
static_assert(std::is_same_v<decltype(safegi::pow<-2>(length{})), quantity<dim::pdf_area>>);
static_assert(std::is_same_v<decltype(safegi::acos(0.5f)), angle>);
static_assert(std::is_same_v<decltype(safegi::atan2(length{}, length{})), angle>);
// Mixing plain numbers into + - < needs a dimensionless quantity (checked only by the
// compile-fail suite); scaling by a plain number is always fine.
static_assert(std::is_same_v<decltype(length{} * 2), length>);
static_assert(std::is_same_v<decltype(2.0 * length{}), length>);

constexpr length metres(float v) { return from_raw<length>(v); }

TEST(Quantity, AdditionKeepsTheDimension) {
  EXPECT_FLOAT_EQ(raw(metres(1.5f) + metres(2.0f)), 3.5f);
  EXPECT_FLOAT_EQ(raw(metres(1.5f) - metres(2.0f)), -0.5f);
  length x = metres(1.0f);
  x += metres(2.0f);
  x -= metres(0.5f);
  x *= 4;
  x /= 2.0f;
  EXPECT_FLOAT_EQ(raw(x), 5.0f);
  EXPECT_FLOAT_EQ(raw(-x), -5.0f);
}

TEST(Quantity, ProductsCombineDimensions) {
  const area a = metres(2.0f) * metres(3.0f);
  EXPECT_FLOAT_EQ(raw(a), 6.0f);
  const float ratio = a / area(metres(1.0f) * metres(1.5f));
  EXPECT_FLOAT_EQ(ratio, 4.0f);
  EXPECT_FLOAT_EQ(raw(2.0f / metres(4.0f)), 0.5f);
  EXPECT_FLOAT_EQ(raw(metres(3.0f) / 2), 1.5f);
}

TEST(Quantity, ComparisonsAndZero) {
  EXPECT_LT(metres(1.0f), metres(2.0f));
  EXPECT_GE(metres(2.0f), metres(2.0f));
  EXPECT_EQ(metres(2.0f), metres(2.0f));
  EXPECT_NE(metres(2.0f), metres(3.0f));
  EXPECT_TRUE(metres(1.0f) > zero);
  EXPECT_TRUE(metres(-1.0f) < zero);
  EXPECT_TRUE(metres(0.0f) == zero);
  const quantity<dim::radiance> black = zero;
  EXPECT_EQ(raw(black), 0.0f);
  const float plain = zero;
  EXPECT_EQ(plain, 0.0f);
  EXPECT_TRUE(1.0f > zero);
}

TEST(Quantity, DefaultIsZero) {
  const length x;
  EXPECT_EQ(raw(x), 0.0f);
}

TEST(Quantity, SqrtHalvesEvenExponents) {
  EXPECT_FLOAT_EQ(raw(safegi::sqrt(metres(3.0f) * metres(3.0f))), 3.0f);
  const quantity<dim::pow<dim::radiance, 2>> l2 = from_raw<quantity<dim::pow<dim::radiance, 2>>>(16.0f);
  EXPECT_FLOAT_EQ(raw(safegi::sqrt(l2)), 4.0f);
  EXPECT_EQ(raw(safegi::safe_sqrt(from_raw<area>(-1e-9f))), 0.0f);
  EXPECT_FLOAT_EQ(safegi::sqrt(2.0f), std::sqrt(2.0f));
}

TEST(Quantity, IntegerPowers) {
  EXPECT_FLOAT_EQ(raw(safegi::pow<3>(metres(2.0f))), 8.0f);
  EXPECT_FLOAT_EQ(raw(safegi::pow<-2>(metres(2.0f))), 0.25f);
  EXPECT_FLOAT_EQ(safegi::pow<0>(metres(2.0f)), 1.0f);
  EXPECT_FLOAT_EQ(safegi::pow(2.0f, 0.5f), std::sqrt(2.0f));
}

TEST(Quantity, TrigonometryTakesAndGivesAngles) {
  const angle right = 90.0f * units::degree;
  EXPECT_NEAR(safegi::sin(right), 1.0f, 1e-6f);
  EXPECT_NEAR(safegi::cos(right), 0.0f, 1e-6f);
  EXPECT_NEAR(safegi::tan(45.0f * units::degree), 1.0f, 1e-6f);
  EXPECT_NEAR(in(safegi::acos(0.5f), units::degree), 60.0f, 1e-4f);
  EXPECT_NEAR(in(safegi::asin(0.5f), units::degree), 30.0f, 1e-4f);
  EXPECT_NEAR(in(safegi::atan(1.0f), units::degree), 45.0f, 1e-4f);
  EXPECT_NEAR(in(safegi::atan2(metres(1.0f), metres(-1.0f)), units::degree), 135.0f, 1e-4f);
}

TEST(Quantity, ExpLogAndHelpers) {
  EXPECT_FLOAT_EQ(safegi::exp(metres(2.0f) / metres(1.0f)), std::exp(2.0f));
  EXPECT_FLOAT_EQ(safegi::log(std::exp(1.0f)), 1.0f);
  EXPECT_EQ(safegi::abs(metres(-2.0f)), metres(2.0f));
  EXPECT_EQ(safegi::min(metres(1.0f), metres(2.0f)), metres(1.0f));
  EXPECT_EQ(safegi::max(metres(1.0f), metres(2.0f)), metres(2.0f));
  EXPECT_EQ(safegi::clamp(metres(5.0f), metres(0.0f), metres(2.0f)), metres(2.0f));
  EXPECT_EQ(safegi::clamp(metres(-5.0f), metres(0.0f), metres(2.0f)), metres(0.0f));
  EXPECT_FLOAT_EQ(raw(safegi::lerp(metres(1.0f), metres(3.0f), 0.25f)), 1.5f);
  EXPECT_TRUE(safegi::isfinite(metres(1.0f)));
  EXPECT_FALSE(safegi::isfinite(metres(std::numeric_limits<float>::infinity())));
  EXPECT_TRUE(safegi::isnan(metres(std::numeric_limits<float>::quiet_NaN())));
}

// std::numeric_limits of a quantity: the representation's numbers, in the quantity's
// dimension (the primary template answered zero: a ray reaching infinity() missed everything).
static_assert(std::numeric_limits<length>::is_specialized);
static_assert(std::numeric_limits<length>::has_infinity);
static_assert(std::numeric_limits<length>::digits == std::numeric_limits<float>::digits);
static_assert(std::is_same_v<decltype(std::numeric_limits<quantity<dim::radiance>>::infinity()), quantity<dim::radiance>>);
static_assert(std::is_same_v<decltype(std::numeric_limits<quantity<dim::length, double>>::max()),
                             quantity<dim::length, double>>);
static_assert(raw(std::numeric_limits<length>::infinity()) == std::numeric_limits<float>::infinity());
static_assert(raw(std::numeric_limits<length>::max()) == std::numeric_limits<float>::max());
static_assert(raw(std::numeric_limits<length>::lowest()) == std::numeric_limits<float>::lowest());
static_assert(raw(std::numeric_limits<length>::min()) == std::numeric_limits<float>::min());
static_assert(raw(std::numeric_limits<length>::epsilon()) == std::numeric_limits<float>::epsilon());
static_assert(raw(std::numeric_limits<length>::denorm_min()) == std::numeric_limits<float>::denorm_min());
static_assert(raw(std::numeric_limits<quantity<dim::area, double>>::max()) == std::numeric_limits<double>::max());

TEST(Quantity, NumericLimitsAreTheRepresentationsInTheDimension) {
  const length far = std::numeric_limits<length>::infinity();
  EXPECT_TRUE(safegi::isinf(far));
  EXPECT_GT(far, metres(1e30f));
  EXPECT_LT(std::numeric_limits<length>::lowest(), metres(-1e30f));
  EXPECT_TRUE(safegi::isnan(std::numeric_limits<length>::quiet_NaN()));
  EXPECT_TRUE(safegi::isnan(std::numeric_limits<quantity<dim::radiance>>::signaling_NaN()));
  EXPECT_EQ(metres(1.0f) + std::numeric_limits<length>::epsilon(), metres(1.0f + std::numeric_limits<float>::epsilon()));
  EXPECT_TRUE(safegi::isinf(std::numeric_limits<quantity<dim::time, double>>::infinity()));
}

TEST(Quantity, IsinfIsnanIsfiniteSignbitTakeAnyDimension) {
  const length inf = std::numeric_limits<length>::infinity();
  EXPECT_TRUE(safegi::isinf(inf));
  EXPECT_TRUE(safegi::isinf(-inf));
  EXPECT_FALSE(safegi::isinf(metres(1.0f)));
  EXPECT_FALSE(safegi::isinf(std::numeric_limits<length>::quiet_NaN()));
  EXPECT_FALSE(safegi::isfinite(inf));
  EXPECT_FALSE(safegi::isnan(inf));
  EXPECT_TRUE(safegi::signbit(-inf));
  EXPECT_TRUE(safegi::signbit(metres(-0.0f)));
  EXPECT_FALSE(safegi::signbit(metres(0.0f)));
  EXPECT_TRUE(safegi::isinf(std::numeric_limits<float>::infinity() * units::radiance_unit));
  EXPECT_TRUE(safegi::isinf(std::numeric_limits<float>::infinity()));  // plain numbers too
}

TEST(Quantity, DimensionCastIsTheOneEscapeHatch) {
  const quantity<dim::brdf> f = dimension_cast<dim::brdf>(0.25f);
  EXPECT_EQ(raw(f), 0.25f);
  const quantity<dim::irradiance> e = dimension_cast<dim::irradiance>(f);
  EXPECT_EQ(raw(e), 0.25f);
  const float back = dimension_cast<dim::dimensionless>(e);
  EXPECT_EQ(back, 0.25f);
}

TEST(Quantity, DoublePrecision) {
  const quantity<dim::length, double> d = 1e300 * units::kilometre;
  EXPECT_DOUBLE_EQ(raw(d), 1e303);
  static_assert(std::is_same_v<decltype(d * d), const quantity<dim::area, double>> ||
                std::is_same_v<decltype(d * d), quantity<dim::area, double>>);
}

TEST(Quantity, ConstexprArithmetic) {
  constexpr length a = metres(2.0f);
  constexpr area b = a * a;
  static_assert(raw(b) == 4.0f);
  static_assert(raw(safegi::pow<2>(a)) == 4.0f);
  static_assert(a > zero);
  SUCCEED();
}
}  // namespace

namespace {
// max(x, zero) is how a clamped cosine is written; zero has every dimension.
TEST(Quantity, MinAndMaxWithZero) {
  using namespace safegi;
  const quantity<dim::proj> negative = -0.5f * units::proj;
  const quantity<dim::proj> positive = 0.25f * units::proj;
  EXPECT_EQ(raw(safegi::max(negative, zero)), 0.0f);
  EXPECT_EQ(raw(safegi::max(zero, positive)), 0.25f);
  EXPECT_EQ(raw(safegi::min(positive, zero)), 0.0f);
  EXPECT_EQ(raw(safegi::min(zero, negative)), -0.5f);
  static_assert(std::is_same_v<decltype(safegi::max(negative, zero)), quantity<dim::proj>>);
  EXPECT_EQ(safegi::max(-2.0f, zero), 0.0f);  // plain numbers too
}
}  // namespace
