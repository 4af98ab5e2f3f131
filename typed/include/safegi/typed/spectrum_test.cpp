#include "safegi/typed/spectrum.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;

static_assert(sizeof(spectrum<dim::radiance>) == sizeof(glm::vec3));
static_assert(std::is_trivially_copyable_v<spectrum<dim::radiance>>);
static_assert(std::is_same_v<decltype(spectrum<dim::radiance>{} * spectrum<dim::brdf>{}),
                             spectrum<dim::product<dim::radiance, dim::brdf>>>);
static_assert(std::is_same_v<decltype(spectrum<dim::radiance>{} * quantity<dim::proj>{}),
                             spectrum<dim::product<dim::radiance, dim::proj>>>);
static_assert(std::is_same_v<decltype(spectrum<dim::radiance>{} * 2.0f), spectrum<dim::radiance>>);
static_assert(std::is_same_v<decltype(1.0f / spectrum<dim::radiance>{}), spectrum<dim::inverse<dim::radiance>>>);
static_assert(std::is_same_v<decltype(luminance(spectrum<dim::irradiance>{})), quantity<dim::irradiance>>);

spectrum<dim::radiance> radiance(float r, float g, float b) {
  return from_raw<spectrum<dim::radiance>>(glm::vec3(r, g, b));
}

TEST(Spectrum, DirectLightingEstimatorIsRadiance) {
  const spectrum<dim::radiance> Li = radiance(1.0f, 2.0f, 4.0f);
  const spectrum<dim::brdf> f = dimension_cast<dim::brdf>(spectrum<dim::dimensionless>(0.5f / pi));
  const quantity<dim::proj> cosine = dimension_cast<dim::proj>(0.5f);
  const quantity<dim::pdf_solid_angle> pdf = 1.0f / (2.0f * pi * units::steradian);
  const spectrum<dim::radiance> Lo = Li * f * cosine / pdf;
  EXPECT_NEAR(raw(Lo.r()), 0.5f, 1e-6f);
  EXPECT_NEAR(raw(Lo.g()), 1.0f, 1e-6f);
  EXPECT_NEAR(raw(Lo[2]), 2.0f, 1e-6f);
}

TEST(Spectrum, ArithmeticAndHelpers) {
  spectrum<dim::radiance> L = radiance(1, 2, 3);
  L += radiance(1, 1, 1);
  L -= radiance(0, 1, 0);
  L *= 2;
  L /= 2.0f;
  EXPECT_EQ(L, radiance(2, 2, 4));
  EXPECT_EQ(L + L, radiance(4, 4, 8));
  EXPECT_EQ(L - L, spectrum<dim::radiance>{});
  EXPECT_EQ(-L, radiance(-2, -2, -4));
  EXPECT_TRUE(is_black(spectrum<dim::radiance>(zero)));
  EXPECT_FALSE(is_black(L));
  EXPECT_FLOAT_EQ(raw(max_component(L)), 4.0f);
  EXPECT_FLOAT_EQ(raw(average(L)), 8.0f / 3.0f);
  EXPECT_FLOAT_EQ(raw(luminance(radiance(1, 1, 1))), 1.0f);
  EXPECT_EQ(lerp(radiance(0, 0, 0), radiance(2, 4, 8), 0.5f), radiance(1, 2, 4));
  const spectrum<dim::dimensionless> ratio = L / L;
  EXPECT_EQ(raw(ratio), glm::vec3(1.0f));
  L *= ratio;
  EXPECT_EQ(L, radiance(2, 2, 4));
  const spectrum<dim::radiance> grey(1.5f * units::radiance_unit);
  EXPECT_EQ(raw(grey), glm::vec3(1.5f));
  const spectrum<dim::radiance> rgb(1.0f * units::radiance_unit, 2.0f * units::radiance_unit, zero);
  EXPECT_EQ(raw(rgb), glm::vec3(1, 2, 0));
}

TEST(Spectrum, TransmittanceIsExpOfDimensionless) {
  const spectrum<dim::pdf_length> sigma = from_raw<spectrum<dim::pdf_length>>(glm::vec3(1, 2, 3));
  const spectrum<dim::dimensionless> tr = safegi::exp(-sigma * (0.5f * units::metre));
  EXPECT_FLOAT_EQ(raw(tr).g, std::exp(-1.0f));
  const spectrum<dim::area> a = from_raw<spectrum<dim::area>>(glm::vec3(4, 9, 16));
  EXPECT_EQ(raw(safegi::sqrt(a)), glm::vec3(2, 3, 4));
}
}  // namespace
