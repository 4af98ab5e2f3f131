#include "safegi/typed/dimension.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/dimension_name.hpp"

namespace {
using namespace safegi;

SAFEGI_BASE_DIMENSION(pixel);
struct apple_base : base_dimension<"apple"> {};
using apple = dim::of<apple_base>;
struct zebra_base : base_dimension<"zebra"> {};
using zebra = dim::of<zebra_base>;

// Canonical form: the order in which factors are multiplied never shows in the type.
static_assert(std::is_same_v<dim::product<dim::length, dim::time>, dim::product<dim::time, dim::length>>);
static_assert(std::is_same_v<dim::product<zebra, apple, pixel>, dim::product<pixel, zebra, apple>>);
static_assert(std::is_same_v<dim::product<zebra, apple>, dimension<term<apple_base, 1>, term<zebra_base, 1>>>);
// Zero exponents are dropped.
static_assert(std::is_same_v<dim::quotient<dim::length, dim::length>, dim::dimensionless>);
static_assert(std::is_same_v<dim::product<dim::area, dim::inverse<dim::length>>, dim::length>);
static_assert(std::is_same_v<dim::pow<dim::radiance, 0>, dim::dimensionless>);
// The vocabulary is consistent with its definitions.
static_assert(std::is_same_v<dim::power, decltype(dim::energy{} / dim::time{})>);
static_assert(std::is_same_v<dim::irradiance, dim::quotient<dim::power, dim::area>>);
static_assert(std::is_same_v<dim::radiance,
                             dim::quotient<dim::irradiance, dim::product<dim::solid_angle, dim::proj>>>);
static_assert(std::is_same_v<dim::brdf, dim::pdf_projected_solid_angle>);
// Radiance × BRDF × cosine / pdf(solid angle) is radiance again: the Monte Carlo estimator.
static_assert(std::is_same_v<dim::product<dim::radiance, dim::brdf, dim::proj, dim::inverse<dim::pdf_solid_angle>>,
                             dim::radiance>);
// ...and without the cosine it is not.
static_assert(!std::is_same_v<dim::product<dim::radiance, dim::brdf, dim::inverse<dim::pdf_solid_angle>>,
                              dim::radiance>);
// vocabulary.def gives dimensions by exponents; these are the formulas they stand for.
static_assert(std::is_same_v<dim::velocity, dim::quotient<dim::length, dim::time>>);
static_assert(std::is_same_v<dim::intensity, dim::quotient<dim::power, dim::solid_angle>>);
static_assert(std::is_same_v<dim::projected_solid_angle, dim::product<dim::solid_angle, dim::proj>>);
static_assert(std::is_same_v<dim::brdf, dim::inverse<dim::projected_solid_angle>>);
static_assert(std::is_same_v<dim::solid_angle_per_projected_area,
                             dim::quotient<dim::solid_angle, dim::product<dim::area, dim::proj>>>);
static_assert(std::is_same_v<dim::radiant_exitance, dim::irradiance>);
static_assert(std::is_same_v<dim::inv_length, dim::pdf_length>);
static_assert(std::is_same_v<dim::inv_area, dim::pdf_area>);
static_assert(std::is_same_v<dim::root<dim::area, 2>, dim::length>);
static_assert(dim::has_root<dim::pow<dim::radiance, 2>, 2>);
static_assert(!dim::has_root<dim::volume, 2>);
static_assert(std::is_same_v<dim::pow<dim::length, -3>, dim::inverse<dim::volume>>);

TEST(Dimension, NamesComeFromTheVocabulary) {
  EXPECT_EQ(dimension_name<dim::radiance>(), "radiance");
  EXPECT_EQ(dimension_name<dim::irradiance>(), "irradiance");
  EXPECT_EQ(dimension_name<dim::dimensionless>(), "dimensionless");
  EXPECT_EQ(dimension_name<dim::pdf_area>(), "pdf_area");
  EXPECT_EQ(dimension_name<dim::brdf>(), "brdf or pdf_projected_solid_angle");
}

TEST(Dimension, UnnamedDimensionsShowTheirFormula) {
  EXPECT_EQ((dimension_name<dim::product<dim::length, dim::length, dim::time, pixel>>()), "length^2*pixel*time");
  EXPECT_EQ(dimension_name<dim::inverse<dim::time>>(), "time^-1");
  EXPECT_EQ(dimension_formula<dim::radiance>(), "energy*length^-2*proj^-1*solid_angle^-1*time^-1");
  EXPECT_EQ((dimension_name<dim::pow<dim::length, -12>>()), "length^-12");
}

using pixel_density = dim::quotient<pixel, dim::length>;
}  // namespace

template <>
struct safegi::dimension_label<pixel_density> {
  static constexpr std::string_view name = "pixel_density";
};

namespace {
TEST(Dimension, UserLabelsNameUserDimensions) {
  EXPECT_EQ(dimension_name<pixel_density>(), "pixel_density");
  EXPECT_EQ(dimension_text<pixel_density>.view(), "pixel_density");
  EXPECT_EQ(dimension_formula<pixel_density>(), "length^-1*pixel");
}

TEST(Dimension, NamesAreCompileTimeStrings) {
  static_assert(dimension_text<dim::radiance>.view() == "radiance");
  static_assert(dimension_name<dim::area>() == "area");
  SUCCEED();
}
}  // namespace
