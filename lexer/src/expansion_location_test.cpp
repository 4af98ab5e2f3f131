// Every token keeps where it came from: the spelling range, and through the
// expansion table the macro and the place it was expanded.

#include "preprocessor_test_support.hpp"

namespace safegi::testing {
namespace {

using ExpansionLocations = PreprocessorTest;

TEST_F(ExpansionLocations, PlainTokensHaveNoExpansion) {
  auto unit = run("float x;\n");
  EXPECT_EQ(unit.tokens[1].expansion, kNoExpansion);
  EXPECT_EQ(unit.tokens[1].range, sources.range_of(main, 6, 7));
}

TEST_F(ExpansionLocations, ObjectLikeMacroBodyTokens) {
  auto unit = run("#define PI 3.14159\nfloat x = PI;\n");
  const Token& pi = unit.tokens[3];
  EXPECT_EQ(pi.text, "3.14159");
  EXPECT_EQ(pi.range.begin.line, 1u);  // spelled in the #define
  EXPECT_EQ(pi.range.begin.column, 12u);
  ASSERT_NE(pi.expansion, kNoExpansion);
  const MacroExpansion& e = sources.expansion(pi.expansion);
  EXPECT_EQ(e.name, "PI");
  EXPECT_EQ(e.definition.begin.column, 9u);
  EXPECT_EQ(e.expansion_site, sources.range_of(main, 29, 31));
  EXPECT_EQ(e.parent, kNoExpansion);
}

TEST_F(ExpansionLocations, FunctionLikeSiteCoversTheArguments) {
  auto unit = run("#define SQ(x) ((x) * (x))\nfloat y = SQ(a);\n");
  const Token& a = unit.tokens[5];
  EXPECT_EQ(a.text, "a");
  EXPECT_EQ(a.range.begin.line, 2u);  // arguments keep their spelling at the call
  EXPECT_EQ(a.range.begin.column, 14u);
  const MacroExpansion& e = sources.expansion(a.expansion);
  EXPECT_EQ(e.name, "SQ");
  EXPECT_EQ(sources.text(main).substr(e.expansion_site.begin.offset, e.expansion_site.length()), "SQ(a)");
}

TEST_F(ExpansionLocations, NestedExpansionsChainToTheOutermostSite) {
  auto unit = run("#define INNER (y + 1)\n#define OUTER(a) (a * INNER)\nfloat z = OUTER(2);\n");
  const Token* y = nullptr;
  for (const Token& t : unit.tokens) {
    if (t.text == "y") y = &t;
  }
  ASSERT_NE(y, nullptr);
  diagnostics.report(Diagnostic::error(y->range, "undeclared identifier 'y'").with_expansion(y->expansion));
  EXPECT_EQ(errors(),
            "main.glsl:1:16: error: undeclared identifier 'y'\n"
            "#define INNER (y + 1)\n"
            "               ^\n"
            "main.glsl:2:23: note: in expansion of macro 'INNER' (defined at main.glsl:1:9)\n"
            "#define OUTER(a) (a * INNER)\n"
            "                      ^~~~~\n"
            "main.glsl:3:11: note: in expansion of macro 'OUTER' (defined at main.glsl:2:9)\n"
            "float z = OUTER(2);\n"
            "          ^~~~~~~~\n");
}

TEST_F(ExpansionLocations, MacroArgumentsExpandedInsideTheOuterExpansion) {
  auto unit = run("#define ONE 1\n#define ID(x) x\nID(ONE)\n");
  ASSERT_EQ(unit.tokens.size(), 2u);
  const MacroExpansion& one = sources.expansion(unit.tokens[0].expansion);
  EXPECT_EQ(one.name, "ONE");
  ASSERT_NE(one.parent, kNoExpansion);
  EXPECT_EQ(sources.expansion(one.parent).name, "ID");
}

TEST_F(ExpansionLocations, FirstTokenOfAnExpansionTakesTheInvocationsLineFlags) {
  auto unit = run("#define DECL float x;\nDECL\n  DECL\n");
  EXPECT_TRUE(unit.tokens[0].at_line_start);
  EXPECT_FALSE(unit.tokens[1].at_line_start);
  EXPECT_TRUE(unit.tokens[3].at_line_start);
  EXPECT_TRUE(unit.tokens[3].leading_space);
}

TEST_F(ExpansionLocations, PredefinedMacroTokensPointAtTheirUse) {
  auto unit = run("#version 300 es\nint v = __VERSION__ + GL_ES;\n");
  const Token& version = unit.tokens[3];
  EXPECT_EQ(version.text, "300");
  EXPECT_EQ(version.range.begin.line, 2u);
  EXPECT_EQ(version.range.begin.column, 9u);
  const Token& es = unit.tokens[5];
  EXPECT_EQ(es.text, "1");
  EXPECT_EQ(es.range.begin.column, 23u);
  EXPECT_EQ(sources.expansion(es.expansion).name, "GL_ES");
}

TEST_F(ExpansionLocations, ErrorsInsideMacroBodiesShowTheExpansion) {
  run("#define BAD(x) x # x\nBAD(1)\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:18: error: '#' is not allowed in a macro body [E-MACRO]\n"
            "#define BAD(x) x # x\n"
            "                 ^\n"
            "help: GLSL has no stringizing operator; only '##' (token pasting) is supported\n");
}

TEST_F(ExpansionLocations, JsonCarriesTheChain) {
  auto unit = run("#define F(x) x @\nF(1)\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:16: error: invalid character '@' in program [E-CHARACTER]\n"
            "#define F(x) x @\n"
            "               ^\n"
            "main.glsl:2:1: note: in expansion of macro 'F' (defined at main.glsl:1:9)\n"
            "F(1)\n"
            "^~~~\n");
  std::string json = render_json(Diagnostic::error(unit.tokens[0].range, "e").with_expansion(unit.tokens[0].expansion),
                                 sources);
  EXPECT_NE(json.find("\"expansions\":[{\"defined_at\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"macro\":\"F\""), std::string::npos) << json;
}

}  // namespace
}  // namespace safegi::testing
