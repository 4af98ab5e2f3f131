#include "safegi/cpu_renderer/unit_expression.hpp"

#include <gtest/gtest.h>

namespace safegi::render {
namespace {

Quantity parse(std::string_view text) {
  std::string error;
  std::optional<Quantity> q = parse_quantity(text, error);
  EXPECT_TRUE(q.has_value()) << text << ": " << error;
  return q.value_or(Quantity{});
}

std::string error_of(std::string_view text) {
  std::string error;
  EXPECT_FALSE(parse_quantity(text, error).has_value()) << text;
  return error;
}

TEST(UnitExpression, ConvertsToReferenceUnits) {
  EXPECT_DOUBLE_EQ(parse("5 mm").value, 0.005);
  EXPECT_EQ(parse("5 mm").dimension, runtime_dim::length);
  EXPECT_DOUBLE_EQ(parse("2 km").value, 2000.0);
  EXPECT_NEAR(parse("180 deg").value, 3.14159265358979, 1e-12);
  EXPECT_EQ(parse("60 deg").dimension, runtime_dim::angle);
  EXPECT_DOUBLE_EQ(parse("100 W").value, 100.0);
  EXPECT_DOUBLE_EQ(parse("40 ms").value, 0.04);
  EXPECT_DOUBLE_EQ(parse("1.5e3 mW").value, 1.5);
}

TEST(UnitExpression, CompoundUnitsAllSpellings) {
  for (const char* text : {"17 W/(m2 sr)", "17 W/m^2/sr", "17 W m^-2 sr^-1", "17 W*m-2*sr-1", "17 W/(m^2*sr)",
                           "17 W\xC2\xB7m-2\xC2\xB7sr-1"}) {
    Quantity q = parse(text);
    EXPECT_EQ(q.dimension, runtime_dim::radiance) << text;
    EXPECT_DOUBLE_EQ(q.value, 17.0) << text;
  }
  Quantity per_mm2 = parse("1 W/(mm2 sr)");
  EXPECT_DOUBLE_EQ(per_mm2.value, 1e6);
  EXPECT_EQ(parse("3 W/sr").dimension, runtime_dim::intensity);
  EXPECT_TRUE(parse("0.5").dimension.is_dimensionless());
}

TEST(UnitExpression, TheVocabularysUnitsByNameAndSymbol) {
  // Scene files take the units of C++ and shaders (vocabulary.def), by symbol or name.
  EXPECT_DOUBLE_EQ(parse("5 millimetre").value, 0.005);
  EXPECT_DOUBLE_EQ(parse("5 millimeter").value, 0.005);
  EXPECT_DOUBLE_EQ(parse("2 h").value, 7200.0);
  EXPECT_DOUBLE_EQ(parse("2 min").value, 120.0);
  EXPECT_DOUBLE_EQ(parse("3 mJ").value, 0.003);
  EXPECT_DOUBLE_EQ(parse("1 square_millimetre").value, 1e-6);
  EXPECT_EQ(parse("17 radiance_unit").dimension, runtime_dim::radiance);  // no proj in a scene
  EXPECT_EQ(parse("17 watt / (square_metre steradian)").dimension, runtime_dim::radiance);
}

TEST(UnitExpression, Errors) {
  EXPECT_EQ(error_of("5 parsecs"), "unknown unit 'parsecs'");
  EXPECT_EQ(error_of("m"), "expected a number followed by a unit");
  EXPECT_EQ(error_of("5 W/(m2 sr"), "missing ')'");
  EXPECT_EQ(error_of("5 m^"), "missing exponent after '^'");
  EXPECT_EQ(error_of("5 W/"), "missing unit after operator");
  EXPECT_EQ(error_of("5 m^99"), "exponent out of range");
  EXPECT_EQ(error_of("5 m)"), "unexpected ')'");
}

TEST(UnitExpression, DescribesDimensions) {
  EXPECT_EQ(describe(runtime_dim::power), "power (e.g. W)");
  EXPECT_EQ(describe(runtime_dim::radiance), "radiance (e.g. W/(m2 sr))");
  EXPECT_EQ(dimension_name(runtime_dim::length), "length");
  EXPECT_EQ(dimension_name(runtime_dim::make(1, -1, 0, 0, 0)), "m s^-1");
}

}  // namespace
}  // namespace safegi::render
