// Units and conversions: quantities measured in units, `x in unit` and
// `p in space` (docs/language.md, "Units" and "Conversions").

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

const ConversionInfo* only_conversion(const CheckedSource& c) {
  if (c.result.conversions.size() != 1) return nullptr;
  return &c.result.conversions.begin()->second;
}

TEST(Units, UnitsTravelThroughTheAlgebra) {
  auto c = check_source(
      "uniform float<length in centimeter> r;\n"
      "template<dimension D> float<D> twice(float<D> x) { return x + x; }\n"
      "void main() {\n"
      "  float<area in centimeter^2> a = r * r;\n"
      "  float<length in centimeter> back = sqrt(a);\n"
      "  float<length in centimeter> doubled = twice(r);\n"
      "  float<1> ratio = r / back;\n"
      "  float<length> m = r in meter;\n"
      "}\n");
  ASSERT_EQ(c->messages(), Messages{});
  EXPECT_EQ(declared_type(*c, "a"), "float<area in centimeter²>");
  EXPECT_EQ(declared_type(*c, "m"), "float<length>");
}

TEST(Units, MixingUnitsIsAMismatchWithTheFactor) {
  auto c = check_source("uniform float<length in centimeter> r; void main() { float<length> m = r; }");
  ASSERT_EQ(c->messages(), Messages{"error: cannot initialize 'm' of type float<length> with a value of type float<length in centimeter>"});
  EXPECT_EQ(c->diagnostics.diagnostics()[0].hint,
            "the same length in another unit, centimeter where meter is expected: convert it, x in meter (× 0.01)");
  EXPECT_EQ(check_source("uniform float<length in centimeter> r; uniform float<length in inch> i; void main() { bool b = r < i; }")
                ->messages(),
            Messages{"error: cannot compare float<length in centimeter> and float<length in inch>"});
}

TEST(Units, ConversionFactors) {
  auto c = check_source("uniform float<length in centimeter> r; void main() { float<length in inch> i = r in inch; }");
  ASSERT_EQ(c->messages(), Messages{});
  const ConversionInfo* info = only_conversion(*c);
  ASSERT_NE(info, nullptr);
  EXPECT_DOUBLE_EQ(info->factor, 0.01 / 0.0254);
  EXPECT_TRUE(info->maps.empty());
  // A unit of the same scale converts by 1: the elider emits nothing.
  auto same = check_source("unit centimetre : length = 0.01; uniform float<length in centimeter> r;"
                           " void main() { float<length in centimetre> s = r in centimetre; }");
  ASSERT_EQ(same->messages(), Messages{});
  EXPECT_DOUBLE_EQ(only_conversion(*same)->factor, 1.0);
}

TEST(Units, ScalesAreFoldedConstants) {
  auto c = check_source("unit foot : length = 12.0 * inch; unit bad : length = 0.0;\n"
                        "uniform float<length in foot> f; void main() { float<length> m = f in meter; }");
  EXPECT_EQ(c->messages(), Messages{"error: the scale of unit 'bad' must be a positive finite number"});
  ASSERT_NE(c->result.registry.find_unit("foot"), nullptr);
  EXPECT_DOUBLE_EQ(c->result.registry.find_unit("foot")->scale, 12.0 * 0.0254);
}

TEST(Units, CastsKeepTheNumber) {
  EXPECT_EQ(check_source("void main() { float<length in centimeter> r = float<length in centimeter>(5.0); }")->messages(),
            Messages{});
  EXPECT_EQ(check_source("uniform float<length> m; void main() { float<length in centimeter> r = float<length in centimeter>(m); }")
                ->messages(),
            Messages{"error: a cast to float<length in centimeter> would read meter as centimeter: a cast keeps the number"});
  EXPECT_EQ(check_source("void main() { float<length in second> r; }")->messages(), Messages{"error: second measures time, not length"});
}

const char* kSpaces =
    "space object; space world; space view; space clip;\n"
    "uniform map<object, world> worldFromObject;\n"
    "uniform rigidmap<world, view> viewFromWorld;\n"
    "uniform projmap<view, clip> clipFromView;\n"
    "uniform point<object> p; uniform normal<object> n; uniform direction<world> d;\n";

TEST(Conversions, TheShortestChainOfMaps) {
  auto c = check_source(std::string(kSpaces) + "void main() { hpoint<clip> h = p in clip; }");
  ASSERT_EQ(c->messages(), Messages{});
  const ConversionInfo* info = only_conversion(*c);
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->maps, (std::vector<std::string>{"clipFromView", "viewFromWorld", "worldFromObject"}));
  EXPECT_EQ(info->op, GeometricOp::project);
  auto kinds = check_source(std::string(kSpaces) +
                            "void main() { normal<view> nv = n in view; direction<view> dv = d in view; point<object> same = p in object; }");
  ASSERT_EQ(kinds->messages(), Messages{});
  auto widened = check_source(std::string(kSpaces) + "uniform direction<object> od; void main() { direction<view> dv = od in view; }");
  EXPECT_EQ(widened->messages(),
            Messages{"error: cannot initialize 'dv' of type direction<view> with a value of type vector<view, dimensionless>"});
}

TEST(Conversions, LocalMapsAndShadowing) {
  // A local map in scope is a candidate; one that shadows a uniform replaces it.
  auto c = check_source(std::string(kSpaces) +
                        "void main() { map<object, world> worldFromObject = inverse(inverse(worldFromObject));"
                        " point<world> w = p in world; }");
  ASSERT_EQ(c->messages(), Messages{});
}

TEST(Conversions, NoChainAndTwoChains) {
  EXPECT_EQ(check_source(std::string(kSpaces) + "space light; void main() { point<light> l = p in light; }")->messages(),
            Messages{"error: cannot convert point<object> 'p' to light: no chain of maps in scope leads from object to light"});
  EXPECT_EQ(check_source(std::string(kSpaces) + "uniform map<object, world> prev; void main() { point<world> w = p in world; }")
                ->messages(),
            Messages{"error: cannot convert point<object> 'p' to world: two maps lead there, worldFromObject and prev"});
  EXPECT_EQ(check_source(std::string(kSpaces) + "void main() { vec3 v = vec3(1.0) in world; }")->messages(),
            Messages{"error: cannot convert vec3<dimensionless> to world: only points, vectors, directions, normals and hpoints "
                     "are in a space"});
}

}  // namespace
}  // namespace safegi::testing
