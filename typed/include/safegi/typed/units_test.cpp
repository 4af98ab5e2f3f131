#include "safegi/typed/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using namespace safegi;

static_assert(std::is_same_v<decltype(5.0f * units::millimetre), quantity<dim::length>>);
static_assert(std::is_same_v<decltype(units::watt / units::square_metre), unit<dim::irradiance>>);
static_assert(std::is_same_v<decltype(1.0f * units::watt / (units::square_metre * units::steradian * units::proj)),
                             quantity<dim::radiance>>);
static_assert(std::is_same_v<decltype(units::joule / units::second), unit<dim::power>>);
static_assert(std::is_same_v<decltype(pow<2>(units::metre)), unit<dim::area>>);

// Both spellings of a unit (vocabulary.def) are one unit, as in shaders.
static_assert(std::is_same_v<decltype(units::meter), decltype(units::metre)>);
static_assert(units::meter.factor == units::metre.factor && units::centimeter.factor == units::centimetre.factor);
static_assert(units::watt_per_square_meter.factor == units::watt_per_square_metre.factor);

TEST(Units, TheVocabularysUnitsWithTheirScales) {
  EXPECT_DOUBLE_EQ(raw(1.0 * units::hour), 3600.0);
  EXPECT_DOUBLE_EQ(raw(1.0 * units::foot), 0.3048);
  EXPECT_DOUBLE_EQ(raw(180.0 * units::degree), 3.14159265358979323846);
  EXPECT_DOUBLE_EQ(raw(1.0 * units::square_millimeter), 1e-6);
}

TEST(Units, ValuesAreStoredInReferenceUnits) {
  EXPECT_FLOAT_EQ(raw(5.0f * units::millimetre), 0.005f);
  EXPECT_FLOAT_EQ(raw(2.0f * units::kilometre), 2000.0f);
  EXPECT_FLOAT_EQ(raw(1.0f * units::inch), 0.0254f);
  EXPECT_FLOAT_EQ(raw(1.0f * units::foot), 0.3048f);
  EXPECT_FLOAT_EQ(raw(250.0f * units::millisecond), 0.25f);
  EXPECT_FLOAT_EQ(raw(2.0f * units::hour), 7200.0f);
  EXPECT_FLOAT_EQ(raw(180.0f * units::degree), 3.14159265f);
  EXPECT_FLOAT_EQ(raw(3.0f * units::kilowatt), 3000.0f);
  EXPECT_FLOAT_EQ(raw(1.0f * units::kilojoule), 1000.0f);
}

TEST(Units, InConvertsBack) {
  const auto d = 12.0f * units::inch;
  EXPECT_FLOAT_EQ(in(d, units::foot), 1.0f);
  EXPECT_FLOAT_EQ(in(d, units::millimetre), 304.8f);
  EXPECT_FLOAT_EQ(in(1.0f * units::kilometre, units::metre), 1000.0f);
  EXPECT_NEAR(in(3.14159265f * units::radian, units::degree), 180.0f, 1e-4f);
}

TEST(Units, CompoundUnits) {
  const quantity<dim::power> p = 60.0f * units::watt;
  const quantity<dim::energy> e = p * (2.0f * units::minute);
  EXPECT_FLOAT_EQ(in(e, units::kilojoule), 7.2f);
  const quantity<dim::irradiance> irr = 3.0f * units::watt_per_square_metre;
  EXPECT_FLOAT_EQ(in(irr * (2.0f * units::square_metre), units::watt), 6.0f);
  const auto per_mm = 4.0f / units::millimetre;  // a number over a unit: a density
  EXPECT_FLOAT_EQ(raw(per_mm), 4000.0f);
  const auto speed = (10.0f * units::metre) / units::second;  // a quantity over a unit
  EXPECT_FLOAT_EQ(raw(speed), 10.0f);
}

// Extreme magnitudes: conversion is one multiplication in the quantity's precision, so
// the relative error stays within a few ulps across the whole normal range.
TEST(Units, ExtremeMagnitudesKeepRelativePrecision) {
  for (float magnitude : {1e-30f, 1e-20f, 1e-10f, 1.0f, 1e10f, 1e20f, 1e30f}) {
    const auto d = magnitude * units::millimetre;
    EXPECT_NEAR(raw(d) / (magnitude * 1e-3f), 1.0f, 4e-7f) << magnitude;
    EXPECT_NEAR(in(d, units::millimetre) / magnitude, 1.0f, 4e-7f) << magnitude;
    const auto k = magnitude * units::kilometre;
    EXPECT_NEAR(in(k, units::kilometre) / magnitude, 1.0f, 4e-7f) << magnitude;
    EXPECT_NEAR(in(k, units::millimetre) / (magnitude * 1e6f), 1.0f, 4e-7f) << magnitude;
  }
}

TEST(Units, SubnormalsSurviveReferenceUnitConversions) {
  const float tiny = std::numeric_limits<float>::denorm_min();
  EXPECT_EQ(raw(tiny * units::metre), tiny);
  EXPECT_EQ(in(tiny * units::metre, units::metre), tiny);
  const float subnormal = 1e-40f;
  ASSERT_EQ(std::fpclassify(subnormal), FP_SUBNORMAL);
  EXPECT_EQ(std::fpclassify(raw(subnormal * units::metre)), FP_SUBNORMAL);
  // A subnormal keeps fewer digits: here about 5, so the round trip is within 1e-5.
  EXPECT_NEAR(in(subnormal * units::kilometre, units::kilometre) / subnormal, 1.0f, 1e-5f);
  EXPECT_EQ(raw(subnormal * units::micrometre), 0.0f);  // below denorm_min: flushes to zero, never NaN
}

TEST(Units, LargestExponents) {
  const float largest = std::numeric_limits<float>::max();
  EXPECT_EQ(raw(largest * units::metre), largest);
  EXPECT_FLOAT_EQ(in(largest * units::millimetre, units::millimetre) / largest, 1.0f);
  EXPECT_TRUE(std::isinf(raw(largest * units::kilometre)));  // overflow is IEEE inf, not UB
  const double big = std::numeric_limits<double>::max() / 1e3;
  EXPECT_DOUBLE_EQ(in(big * units::kilometre, units::kilometre), big);
  EXPECT_DOUBLE_EQ(raw(1e-300 * units::nanometre), 1e-309);
}

TEST(Units, LayoutOfUnitsIsOneDouble) {
  static_assert(sizeof(unit<dim::length>) == sizeof(double));
  SUCCEED();
}
}  // namespace
