#include "safegi/dimension_algebra/registry.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace safegi {
namespace {

class Prelude : public ::testing::Test {
 protected:
  DimensionRegistry r = DimensionRegistry::rendering_prelude();
  Dimension dim(std::initializer_list<std::pair<std::string_view, std::int32_t>> terms) { return *r.make(terms); }
};

TEST_F(Prelude, HasTheRenderingVocabulary) {
  for (const char* base : {"length", "time", "energy", "angle", "solid_angle", "proj"})
    EXPECT_TRUE(r.find_base(base)) << base;
  for (const char* derived : {"area", "power", "intensity", "irradiance", "radiance", "brdf", "pdf_solid_angle",
                              "pdf_projected_solid_angle", "pdf_area"})
    EXPECT_NE(r.find_derived(derived), nullptr) << derived;
  EXPECT_FALSE(r.find_space("world"));  // spaces are the program's own
  EXPECT_TRUE(r.add_space("world"));
  EXPECT_FALSE(r.find_space("length"));
  EXPECT_EQ(r.space_name(*r.find_space("world")), "world");
  EXPECT_FALSE(r.find_base("radiance"));
}

TEST_F(Prelude, RadianceIsPowerPerAreaSolidAngleAndProjection) {
  EXPECT_EQ(dim({{"radiance", 1}}),
            dim({{"energy", 1}, {"time", -1}, {"length", -2}, {"solid_angle", -1}, {"proj", -1}}));
  // Integrating radiance over projected solid angle gives irradiance.
  EXPECT_EQ(dim({{"radiance", 1}, {"solid_angle", 1}, {"proj", 1}}), dim({{"irradiance", 1}}));
  // brdf × radiance × cos × dω = radiance
  EXPECT_EQ(dim({{"brdf", 1}, {"radiance", 1}, {"proj", 1}, {"solid_angle", 1}}), dim({{"radiance", 1}}));
}

TEST_F(Prelude, PrintsTheDerivedNameWhenExact) {
  EXPECT_EQ(r.format(dim({{"radiance", 1}})), "radiance");
  EXPECT_EQ(r.format(dim({{"length", 2}})), "area");
  EXPECT_EQ(r.format(dim({{"length", 1}})), "length");
  // brdf and the projected-solid-angle pdf coincide; the first declared wins.
  EXPECT_EQ(r.format(dim({{"pdf_projected_solid_angle", 1}})), "brdf");
  EXPECT_EQ(r.format(Dimension{}), "dimensionless");
  EXPECT_EQ(DimensionRegistry{}.format(Dimension{}), "1");
  EXPECT_EQ(r.format(dim({{"power", 1}, {"area", -1}})), "irradiance");  // not radiant_exitance
}

TEST_F(Prelude, PrintsSiUnitsForPeople) {
  const std::pair<const char*, const char*> expected[] = {
      {"dimensionless", "1"},      {"length", "m"},          {"area", "m²"},
      {"volume", "m³"},            {"time", "s"},            {"velocity", "m·s⁻¹"},
      {"energy", "J"},             {"power", "W"},           {"intensity", "W·sr⁻¹"},
      {"irradiance", "W·m⁻²"},     {"radiant_exitance", "W·m⁻²"},
      {"radiance", "W·m⁻²·sr⁻¹"},  // proj left out: the cosine is a pure number in SI
      {"brdf", "sr⁻¹"},            {"pdf_solid_angle", "sr⁻¹"}, {"pdf_projected_solid_angle", "sr⁻¹"},
      {"pdf_area", "m⁻²"},         {"pdf_length", "m⁻¹"},    {"inv_area", "m⁻²"},
      {"angle", "rad"},            {"solid_angle", "sr"},    {"proj", "1"},
  };
  for (const auto& [name, units] : expected) EXPECT_EQ(r.format_si(*r.find_dimension(name)), units) << name;
  EXPECT_EQ(r.format_si(*r.find_dimension("radiance"), Notation::ascii), "W*m^-2*sr^-1");
  // Watts take what energy and inverse time share; the rest stays J or s.
  EXPECT_EQ(r.format_si(dim({{"energy", 2}, {"time", -1}})), "W·J");
  EXPECT_EQ(r.format_si(dim({{"energy", 1}, {"time", -2}})), "W·s⁻¹");
  EXPECT_EQ(r.format_si(dim({{"energy", 1}, {"time", 1}})), "J·s");
  EXPECT_EQ(r.format_si(dim({{"power", -1}})), "W⁻¹");
  EXPECT_EQ(r.format_si(dim({{"angle", 1}, {"time", -1}})), "rad·s⁻¹");
  // A program's own base keeps its name, after the SI symbols.
  DimensionRegistry own = DimensionRegistry::rendering_prelude();
  const BaseId pixel = *own.add_base("pixel");
  EXPECT_EQ(own.format_si(*multiply(Dimension::base(pixel, -2), *own.find_dimension("length"))), "m·pixel⁻²");
  // Without the prelude every base is the program's own.
  DimensionRegistry bare;
  const BaseId mass = *bare.add_base("mass");
  EXPECT_EQ(bare.format_si(Dimension::base(mass, 3)), "mass³");
}

TEST_F(Prelude, PrintsANormalisedProductOtherwise) {
  const Dimension d = dim({{"time", -1}, {"length", 2}});
  EXPECT_EQ(r.format(d), "length²·time⁻¹");
  EXPECT_EQ(r.format(d, Notation::ascii), "length^2*time^-1");
  EXPECT_EQ(r.format(dim({{"radiance", 1}, {"proj", 1}})), "energy·length⁻²·time⁻¹·solid_angle⁻¹");
  EXPECT_EQ(r.format(dim({{"length", 12}, {"angle", -10}})), "length¹²·angle⁻¹⁰");
  EXPECT_EQ(r.format_product(dim({{"radiance", 1}}), Notation::ascii),
            "energy*length^-2*time^-1*solid_angle^-1*proj^-1");
}

TEST_F(Prelude, PrintsExtremeExponents) {
  EXPECT_EQ(r.format(Dimension::base(0, INT32_MIN), Notation::ascii), "length^-2147483648");
  EXPECT_EQ(r.format(Dimension::base(0, INT32_MIN)), "length⁻²¹⁴⁷⁴⁸³⁶⁴⁸");
  EXPECT_EQ(r.format_rational({{0, 3, 2}, {1, -1, 3}}), "length^(3/2)·time^(-1/3)");
}

TEST_F(Prelude, UnitsCarryDimensionAndScale) {
  const Unit* degree = r.find_unit("degree");
  ASSERT_NE(degree, nullptr);
  EXPECT_EQ(degree->dimension, dim({{"angle", 1}}));
  EXPECT_DOUBLE_EQ(degree->scale, std::numbers::pi / 180.0);
  EXPECT_EQ(r.find_unit("watt")->dimension, dim({{"power", 1}}));
  EXPECT_EQ(r.find_unit("length"), nullptr);
}

TEST_F(Prelude, NamesAreDeclaredOnce) {
  EXPECT_FALSE(r.add_base("length"));
  EXPECT_FALSE(r.add_derived("meter", Dimension{}));
  EXPECT_FALSE(r.add_space("radiance"));
  EXPECT_FALSE(r.add_unit("meter", Dimension{}, 2.0));
  EXPECT_TRUE(r.is_declared("meter"));
  EXPECT_FALSE(r.make({{"furlong", 1}}));
}

TEST_F(Prelude, UserBasesExtendTheVocabulary) {
  auto pixel = r.add_base("pixel");
  ASSERT_TRUE(pixel);
  EXPECT_EQ(*pixel, 6u);  // after the six prelude bases
  EXPECT_TRUE(r.add_derived("pixel_density", dim({{"pixel", 1}, {"area", -1}})));
  EXPECT_EQ(r.format(dim({{"pixel", 1}, {"length", -2}})), "pixel_density");
  EXPECT_EQ(r.format(dim({{"pixel", 2}, {"length", -2}})), "pixel²·length⁻²");
}

TEST_F(Prelude, LongDerivedChains) {
  DimensionRegistry chain;
  chain.add_base("x");
  chain.add_derived("d0", *chain.make({{"x", 1}}));
  std::string previous = "d0";
  for (int i = 1; i < 40; ++i) {
    const std::string name = "d" + std::to_string(i);
    ASSERT_TRUE(chain.add_derived(name, *chain.make({{previous, 1}, {"x", 1}})));
    previous = name;
  }
  EXPECT_EQ(chain.find_dimension("d39")->exponent(0), 40);
  EXPECT_EQ(chain.format(Dimension::base(0, 40)), "d39");
  EXPECT_EQ(chain.format(Dimension::base(0, 41)), "x⁴¹");
}

// Units are factors of a dimension: centimeter¹ is a length measured in centimetres.
TEST_F(Prelude, UnitFactors) {
  const Dimension cm = r.measured_in(*r.find_unit("centimeter"));
  const Dimension m = r.measured_in(*r.find_unit("meter"));
  EXPECT_EQ(m, dim({{"length", 1}}));  // the reference unit is the dimension itself
  EXPECT_TRUE(r.has_unit_factors(cm));
  EXPECT_FALSE(r.has_unit_factors(m));
  EXPECT_EQ(*r.reference(cm), dim({{"length", 1}}));
  EXPECT_DOUBLE_EQ(r.scale(cm), 0.01);
  const Dimension cm2 = *multiply(cm, cm);
  EXPECT_DOUBLE_EQ(r.scale(cm2), 1e-4);
  EXPECT_EQ(r.format(cm), "length in centimeter");
  EXPECT_EQ(r.format(cm2), "area in centimeter²");
  EXPECT_EQ(r.format(cm2, Notation::ascii), "area in centimeter^2");
  const Dimension per_ms = *divide(cm, r.measured_in(*r.find_unit("millisecond")));
  EXPECT_EQ(r.format(per_ms), "velocity in centimeter·millisecond⁻¹");
  // Reference bases are spelled by their scale-1 unit.
  EXPECT_EQ(r.format(*divide(cm, dim({{"time", 1}}))), "velocity in centimeter·second⁻¹");
  EXPECT_EQ(r.format_units(dim({{"area", 1}})), "meter²");
  EXPECT_EQ(r.format_units(dim({{"proj", -1}})), "proj⁻¹");  // no unit of proj: its base name
  // cm / cm cancels; cm / m does not (a plain number times 0.01).
  EXPECT_TRUE(divide(cm, cm)->is_dimensionless());
  EXPECT_DOUBLE_EQ(r.scale(*divide(cm, m)), 0.01);
  EXPECT_TRUE(r.reference(*divide(cm, m))->is_dimensionless());
  // Units of the same dimension and scale share one factor: the vocabulary's two
  // spellings, and a program's own unit of that scale.
  DimensionRegistry q = DimensionRegistry::rendering_prelude();
  EXPECT_EQ(q.measured_in(*q.find_unit("centimetre")), q.measured_in(*q.find_unit("centimeter")));
  ASSERT_TRUE(q.add_unit("hundredth", *q.find_dimension("length"), 0.01));
  EXPECT_EQ(q.measured_in(*q.find_unit("hundredth")), q.measured_in(*q.find_unit("centimeter")));
}

TEST_F(Prelude, NumbersAsLiterals) {
  EXPECT_EQ(DimensionRegistry::format_number(0.01), "0.01");
  EXPECT_EQ(DimensionRegistry::format_number(100.0), "100.0");
  EXPECT_EQ(DimensionRegistry::format_number(1e-4), "0.0001");
  EXPECT_EQ(DimensionRegistry::format_number(0.017453292519943295), "0.017453292519943295");
  EXPECT_EQ(DimensionRegistry::format_number(1e-9), "1e-09");
  EXPECT_TRUE(DimensionRegistry::same_scale(12.0 * 0.0254, 0.3048));
  EXPECT_FALSE(DimensionRegistry::same_scale(0.01, 0.0100001));
}

TEST_F(Prelude, DescribesErrors) {
  EXPECT_EQ(r.describe({DimensionErrorKind::not_a_root, 0, 3, 2}), "exponent 3 of 'length' is not divisible by 2");
  EXPECT_EQ(r.describe({DimensionErrorKind::exponent_overflow, 1, 1 << 30, 1 << 30}),
            "exponent of 'time' overflows (1073741824 combined with 1073741824 leaves the 32-bit range)");
}

}  // namespace
}  // namespace safegi
