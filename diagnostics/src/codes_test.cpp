#include "safegi/diagnostics/codes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace safegi {
namespace {

TEST(DiagnosticCodes, AreUniqueSortedAndMeanSomething) {
  std::set<std::string> seen;
  std::string previous;
  for (const DiagnosticCode& c : diagnostic_codes()) {
    EXPECT_TRUE(seen.insert(std::string(c.code)).second) << c.code;
    EXPECT_LT(previous, c.code) << "codes.def is sorted by code";
    EXPECT_TRUE(c.code.starts_with("E-") || c.code.starts_with("W-")) << c.code;
    EXPECT_FALSE(c.meaning.empty()) << c.code;
    previous = c.code;
  }
  EXPECT_GE(seen.size(), 60u);
}

TEST(DiagnosticCodes, ConstantsSpellTheCodes) {
  EXPECT_STREQ(code::E_DIMENSION_MISMATCH, "E-DIMENSION-MISMATCH");
  EXPECT_STREQ(code::W_IMPLICIT_ANNOTATION, "W-IMPLICIT-ANNOTATION");
  ASSERT_NE(find_diagnostic_code("E-TEXEL-MISMATCH"), nullptr);
  EXPECT_EQ(find_diagnostic_code("E-DIM-MISMATCH"), nullptr);
}

TEST(DiagnosticCodes, ExplainNamesTheCodeAndItsMeaning) {
  const std::string text = explain_diagnostic_code("E-UNIT-CAST");
  EXPECT_EQ(text.rfind("E-UNIT-CAST: a cast that would change the unit of a quantity", 0), 0u) << text;
  EXPECT_EQ(explain_diagnostic_code("E-NOPE"), "");
}

}  // namespace
}  // namespace safegi
