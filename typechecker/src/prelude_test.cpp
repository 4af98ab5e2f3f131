// The build makes safegi/prelude.sgl from vocabulary.def (cmake/SafeGIPrelude.cmake); the
// checker's DimensionRegistry::rendering_prelude() is made from the same file by the C++
// preprocessor. The generated prelude parses and declares exactly the vocabulary's entries:
// every base, dimension and unit, in the same order, with the same value (a dimension's
// shader formula is checked against its exponents here).

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

std::vector<std::string> listed(const std::vector<std::string>& names) { return names; }

TEST(Prelude, TheGeneratedPreludeDeclaresExactlyTheVocabulary) {
  auto c = check_source("void main() {}");
  ASSERT_EQ(c->rendered(), "");
  const DimensionRegistry& shader = c->result.registry;
  const DimensionRegistry vocabulary = DimensionRegistry::rendering_prelude();

  EXPECT_EQ(listed(shader.bases()), listed(vocabulary.bases()));
  for (BaseId b = 0; b < shader.base_count() && b < vocabulary.base_count(); ++b)
    EXPECT_EQ(shader.is_ratio_base(b), vocabulary.is_ratio_base(b)) << shader.base_name(b);

  std::vector<std::string> shader_derived, vocabulary_derived;
  for (const DerivedDimension& d : shader.derived()) shader_derived.push_back(d.name + " = " + shader.format_product(d.value));
  for (const DerivedDimension& d : vocabulary.derived())
    vocabulary_derived.push_back(d.name + " = " + vocabulary.format_product(d.value));
  EXPECT_EQ(shader_derived, vocabulary_derived);

  std::vector<std::string> shader_units, vocabulary_units;
  auto describe = [](const DimensionRegistry& r, const Unit& u) {
    return u.name + " : " + r.format_product(u.dimension) + " = " + DimensionRegistry::format_number(u.scale);
  };
  for (const Unit& u : shader.units()) shader_units.push_back(describe(shader, u));
  for (const Unit& u : vocabulary.units()) vocabulary_units.push_back(describe(vocabulary, u));
  EXPECT_EQ(shader_units, vocabulary_units);
  EXPECT_FALSE(shader_units.empty());
}

TEST(Prelude, BothSpellingsOfAUnitAreOneUnit) {
  auto c = check_source(
      "uniform float<length in centimetre> a;\n"
      "void main() { float<length in centimeter> b = a; float<length> m = 1.0 * metre + 2.0 * meter; }");
  EXPECT_EQ(c->rendered(), "");
  EXPECT_EQ(declared_type(*c, "a"), "float<length in centimeter>");
}

TEST(Prelude, AUnitRedeclaredAsItIsTakesTheDeclarationAndAnotherScaleIsAnError) {
  // Shaders written before the prelude gained `hour` declared it themselves.
  EXPECT_EQ(check_source("unit hour : time = 3600.0;\nvoid main() {}")->rendered(), "");
  EXPECT_EQ(check_source("unit hour : time = 3000.0;\nvoid main() {}")->messages(),
            (std::vector<std::string>{"error: unit 'hour' is redeclared with scale 3000.0; it was 3600.0"}));
}

}  // namespace
}  // namespace safegi::testing
