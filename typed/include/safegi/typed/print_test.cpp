// Printing: the number in reference units, the unit, and the dimension's name.
#include <gtest/gtest.h>

#include <safegi/typed.hpp>
#include <sstream>

namespace {
namespace sg = safegi;
using namespace sg;
using spaces::world;

SAFEGI_BASE_DIMENSION(pixel);

template <class X>
std::string printed(const X& x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

TEST(Print, RadianceNamesItsUnitAndDimension) {
  const quantity<dim::radiance> L = 2.0f * units::radiance_unit;
  EXPECT_EQ(printed(L), "2 W·m⁻²·sr⁻¹ (radiance)");
  EXPECT_EQ(sg::to_string(L), printed(L));
}

TEST(Print, ReferenceUnitsOfTheVocabulary) {
  EXPECT_EQ(sg::to_string(5.0f * units::millimetre), "0.005 m (length)");
  EXPECT_EQ(sg::to_string(3.0f * units::second), "3 s (time)");
  EXPECT_EQ(sg::to_string(2.0f * units::watt), "2 W (power)");
  EXPECT_EQ(sg::to_string(2.0f * units::joule), "2 J (energy)");
  EXPECT_EQ(sg::to_string(0.5f * units::watt_per_square_metre), "0.5 W·m⁻² (irradiance)");
  EXPECT_EQ(sg::to_string(1.0f * units::watt_per_steradian), "1 W·sr⁻¹ (intensity)");
  EXPECT_EQ(sg::to_string(4.0f * units::square_metre), "4 m² (area)");
  EXPECT_EQ(sg::to_string(1.0f * units::radian), "1 rad (angle)");
  EXPECT_EQ(sg::to_string(1.0f / (2.0f * units::steradian)), "0.5 sr⁻¹ (pdf_solid_angle)");
  EXPECT_EQ(sg::to_string(1.0f / (1.0f * units::steradian * units::proj)), "1 sr⁻¹ (brdf or pdf_projected_solid_angle)");
}

TEST(Print, ProjHasNoUnitButShowsInTheName) {
  EXPECT_EQ(sg::to_string(0.5f * units::proj), "0.5 (proj)");
}

TEST(Print, EveryDimensionOfTheVocabularyByItsName) {
  const auto speed = (3.0f * units::metre) / (2.0f * units::second);
  EXPECT_EQ(sg::to_string(speed), "1.5 m·s⁻¹ (velocity)");  // the shaders' velocity, from vocabulary.def
}

TEST(Print, UnnamedDimensionsShowTheirFormula) {
  const auto acceleration = (3.0f * units::metre) / (2.0f * units::second * units::second);
  EXPECT_EQ(sg::to_string(acceleration), "1.5 m·s⁻² (length*time^-2)");
  EXPECT_EQ(sg::to_string(1.0f * units::joule * units::joule / units::second), "1 J²·s⁻¹ (energy^2*time^-1)");
  EXPECT_EQ(sg::to_string(1.0f / units::watt), "1 W⁻¹ (energy^-1*time)");
  const quantity<dim::product<pixel, dim::length>> user = dimension_cast<dim::product<pixel, dim::length>>(2.0f);
  EXPECT_EQ(sg::to_string(user), "2 m·pixel (length*pixel)");
}

TEST(Print, TheStreamsFormattingAppliesToTheNumber) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << (1.0f / 3.0f) * units::metre;
  EXPECT_EQ(out.str(), "0.333 m (length)");
}

TEST(Print, SpectraPrintTheirChannelsOnce) {
  const spectrum<dim::radiance> L(1.0f * units::radiance_unit, 2.0f * units::radiance_unit,
                                  0.5f * units::radiance_unit);
  EXPECT_EQ(sg::to_string(L), "(1, 2, 0.5) W·m⁻²·sr⁻¹ (radiance)");
  EXPECT_EQ(sg::to_string(spectrum<dim::dimensionless>(0.25f)), "(0.25, 0.25, 0.25)");
}

TEST(Print, GeometryNamesItsKindAndSpace) {
  const point<world> p(1.0f * units::metre, 2.0f * units::metre, 0.0f * units::metre);
  EXPECT_EQ(sg::to_string(p), "point<world>(1 m, 2 m, 0 m)");
  EXPECT_EQ(sg::to_string(p - point<world>{}), "vector<world>(1 m, 2 m, 0 m)");
  EXPECT_EQ(sg::to_string(direction<world>(0, 0, 1)), "direction<world>(0, 0, 1)");
  EXPECT_EQ(sg::to_string(normal<spaces::object>(0, 1, 0)), "normal<object>(0, 1, 0)");
  EXPECT_EQ(sg::to_string(hpoint<spaces::clip>(1, 2, 3, 4)), "hpoint<clip>(1, 2, 3, 4)");
  EXPECT_EQ(sg::to_string(direction<world>(1, 0, 0) * (2.0f * units::watt)),
            "vector<world, power>(2 W, 0 W, 0 W)");
  EXPECT_EQ(sg::to_string(direction<world>(1, 0, 0) + direction<world>(0, 1, 0)),
            "vector<world, dimensionless>(1, 1, 0)");
  EXPECT_EQ(sg::to_string(ray<world>(p, direction<world>(0, 0, 1))),
            "ray(point<world>(1 m, 2 m, 0 m), direction<world>(0, 0, 1))");
}

}  // namespace
