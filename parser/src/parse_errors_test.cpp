// Syntax errors: exact messages, several per run without cascades, recovery
// at ';' and '}', nesting limits, and random input that must neither crash
// nor hang.

#include <random>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

TEST(ParseErrors, MissingSemicolonPointsAfterThePreviousToken) {
  auto parsed = parse_text("void f() {\n  float x = 1.0\n  x = 2.0;\n}\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:2:16: error: expected ';' after declaration, found 'x' [E-SYNTAX]\n"
            "  float x = 1.0\n"
            "               ^\n");
}

TEST(ParseErrors, SeveralErrorsOneEachNoCascade) {
  auto parsed = parse_text(
      "void f() {\n"
      "  float a = ;\n"
      "  a = a +;\n"
      "  if (a > 0.0 { a = 1.0; }\n"
      "  a = 2.0;\n"
      "}\n"
      "uniform vec3 4;\n"
      "float g(float x) { return x * 2.0; }\n"
      "vec3 h() { return vec3(1.0) }\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:2:13: error: expected an expression, found ';' [E-SYNTAX]\n"
            "  float a = ;\n"
            "            ^\n"
            "test.glsl:3:10: error: expected an expression, found ';' [E-SYNTAX]\n"
            "  a = a +;\n"
            "         ^\n"
            "test.glsl:4:15: error: expected ')' after if condition, found '{' [E-SYNTAX]\n"
            "  if (a > 0.0 { a = 1.0; }\n"
            "              ^\n"
            "test.glsl:7:14: error: expected a name after type 'vec3', found '4' [E-SYNTAX]\n"
            "uniform vec3 4;\n"
            "             ^\n"
            "test.glsl:9:28: error: expected ';' after return statement, found '}' [E-SYNTAX]\n"
            "vec3 h() { return vec3(1.0) }\n"
            "                           ^\n");
  // Everything around the errors was still parsed.
  ASSERT_EQ(parsed->unit().decls.size(), 3u);
  const auto* f = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls[0]);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->body->statements.size(), 1u);  // `a = 2.0;`
  EXPECT_EQ(ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls[1])->name, "g");
}

TEST(ParseErrors, UnclosedBlockAtEndOfFile) {
  auto parsed = parse_text("void f() {\n  if (true) {\n    return;\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:3:12: error: expected '}' to close the block opened at line 2, found end of file [E-SYNTAX]\n"
            "    return;\n"
            "           ^\n");
}

TEST(ParseErrors, StrayClosingBraceAtGlobalScope) {
  auto parsed = parse_text("float a;\n}\nfloat b;\n");
  EXPECT_EQ(parsed->diagnostics.error_count(), 1u) << parsed->errors();
  EXPECT_EQ(parsed->unit().decls.size(), 2u);
}

TEST(ParseErrors, MessagesForAnnotations) {
  EXPECT_EQ(parse_text("dimension d = length^;")->errors(),
            "test.glsl:1:22: error: expected an integer exponent after '^', found ';' [E-SYNTAX]\n"
            "dimension d = length^;\n"
            "                     ^\n");
  EXPECT_EQ(parse_text("dimension d = 2 * length;")->errors(),
            "test.glsl:1:15: error: only the literal 1 may appear in a dimension expression, found '2' [E-SYNTAX]\n"
            "dimension d = 2 * length;\n"
            "              ^\n");
  EXPECT_EQ(parse_text("uniform float<length x;")->errors(),
            "test.glsl:1:22: error: expected ',' or '>' in annotation, found 'x' [E-SYNTAX]\n"
            "uniform float<length x;\n"
            "                     ^\n");
  EXPECT_EQ(parse_text("template<dimension D> float<D> x;")->errors(),
            "test.glsl:1:32: error: expected a function declaration after 'template<...>', found 'x' [E-SYNTAX]\n"
            "template<dimension D> float<D> x;\n"
            "                               ^\n");
  EXPECT_EQ(parse_text("template<typename D> float<D> f();")->errors(),
            "test.glsl:1:10: error: expected 'dimension' or 'space' in template parameter list, found 'typename' [E-SYNTAX]\n"
            "template<typename D> float<D> f();\n"
            "         ^~~~~~~~\n");
}

TEST(ParseErrors, DeepNestingIsADiagnosticNotACrash) {
  std::string deep = "void f() { float x = " + std::string(100000, '(') + "1.0" + std::string(100000, ')') + "; }";
  auto parsed = parse_text(deep);
  ASSERT_EQ(parsed->diagnostics.error_count(), 1u);
  EXPECT_NE(parsed->diagnostics.diagnostics()[0].message.find("nesting too deep: more than 256 levels"),
            std::string::npos);

  std::string blocks = "void f() " + std::string(50000, '{') + std::string(50000, '}');
  EXPECT_EQ(parse_text(blocks)->diagnostics.error_count(), 1u);

  std::string unary = "void f() { x = " + std::string(50000, '-') + "x; }";
  EXPECT_EQ(parse_text(unary)->diagnostics.error_count(), 1u);

  std::string ifs = "void f() { ";
  for (int i = 0; i < 20000; ++i) ifs += "if (a) ";
  ifs += "x(); }";
  EXPECT_EQ(parse_text(ifs)->diagnostics.error_count(), 1u);

  std::string annotation = "float" + std::string(5000, '<') + "x;";
  EXPECT_GE(parse_text(annotation)->diagnostics.error_count(), 1u);
}

// Each nested construct is one level (DepthGuard): N parentheses are N
// levels, and the 257th is the one reported, with its caret.
TEST(ParseErrors, NestingCountsEachLevelOnce) {
  auto nested = [](int n, const char* open, const char* inner, const char* close) {
    std::string text;
    for (int i = 0; i < n; ++i) text += open;
    text += inner;
    for (int i = 0; i < n; ++i) text += close;
    return text;
  };
  // The function body is a block: one level of the 256.
  EXPECT_EQ(parse_text("float x = " + nested(256, "(", "1.0", ")") + ";")->errors(), "");
  EXPECT_EQ(parse_text("void f() { x = " + nested(255, "(", "1.0", ")") + "; }")->errors(), "");
  const std::string parens = "void f() { x = " + nested(256, "(", "1.0", ")") + "; }";
  EXPECT_EQ(parse_text(parens)->errors(),
            std::string("test.glsl:1:271: error: nesting too deep: more than 256 levels of blocks, parentheses, brackets or operators [E-LIMIT]\n") +
                "..." + parens.substr(194, 154) + "...\n" + std::string(3 + 76, ' ') + "^\n");  // cut around the caret
  EXPECT_EQ(parse_text("void f() " + nested(256, "{", "", "}"))->errors(), "");
  EXPECT_EQ(parse_text("void f() " + nested(257, "{", "", "}"))->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { x = " + nested(255, "g(", "1.0", ")") + "; }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { x = " + nested(256, "g(", "1.0", ")") + "; }")->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { x = " + nested(255, "a[", "0", "]") + "; }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { x = " + nested(256, "a[", "0", "]") + "; }")->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { x = " + nested(255, "vec4(", "1.0", ")") + "; }")->errors(), "");
  // `if (a) {` is one level (the block), `if (a) if (b)` one per body.
  EXPECT_EQ(parse_text("void f() " + nested(255, "{ if (a) ", "x();", "}"))->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { " + nested(255, "if (a) ", "x = 1;", "") + " }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { " + nested(256, "if (a) ", "x = 1;", "") + " }")->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { " + nested(128, "if (a) {", "x();", "}") + " }")->errors(), "");
  // A chain of prefix operators or assignments nests too: each is one level.
  EXPECT_EQ(parse_text("void f() { x = " + nested(256, "- ", "a", "") + "; }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { x = " + nested(257, "- ", "a", "") + "; }")->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { " + nested(256, "a = ", "b", "") + "; }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { " + nested(257, "a = ", "b", "") + "; }")->diagnostics.error_count(), 1u);
  EXPECT_EQ(parse_text("void f() { x = " + nested(256, "a ? b : ", "c", "") + "; }")->errors(), "");
  EXPECT_EQ(parse_text("void f() { x = " + nested(257, "a ? b : ", "c", "") + "; }")->diagnostics.error_count(), 1u);
}

TEST(ParseErrors, LongOperatorChainsAreLimitedByHeight) {
  std::string chain = "void f() { x = a";
  for (int i = 0; i < 5000; ++i) chain += " + a";
  chain += "; }";
  auto parsed = parse_text(chain);
  ASSERT_EQ(parsed->diagnostics.error_count(), 1u);
  EXPECT_NE(parsed->diagnostics.diagnostics()[0].message.find("expression too deeply nested"), std::string::npos);

  std::string ok = "void f() { x = a";
  for (int i = 0; i < 1000; ++i) ok += " + a";
  ok += "; }";
  EXPECT_FALSE(parse_text(ok)->diagnostics.has_errors());
}

// Random token soup from GLSL and annotation vocabulary: every input must
// terminate with or without diagnostics. Bounded and seeded, so it is fast
// and reproducible.
TEST(ParseErrors, RandomInputNeverCrashesOrHangs) {
  const char* vocabulary[] = {
      "float", "vec3",  "point", "map",   "<",      ">",      ">>",     ">=",   "(",      ")",      "{",
      "}",     "[",     "]",     ";",     ",",      "=",      "+",      "-",    "*",      "/",      "^",
      "x",     "y",     "1",     "0.5",   "if",     "else",   "for",    "while", "do",    "return", "struct",
      "uniform", "in",  "layout", "dimension", "unit", "space", "template", ":", "?",   ".",      "length",
      "switch", "case", "default", "break", "precision", "highp", "void", "sampler2D", "const", "++", "&&"};
  std::mt19937 rng(12345);
  std::uniform_int_distribution<std::size_t> pick(0, std::size(vocabulary) - 1);
  std::uniform_int_distribution<int> length(1, 200);
  for (int round = 0; round < 1500; ++round) {
    std::string text;
    for (int i = length(rng); i > 0; --i) {
      text += vocabulary[pick(rng)];
      text += ' ';
    }
    auto parsed = parse_text(text);
    ASSERT_NE(parsed->result.unit, nullptr);
    (void)parsed->glsl();  // printing a partial tree must work too
    (void)parsed->dump();
  }
}

TEST(ParseErrors, RandomMutationsOfAValidShader) {
  const std::string shader =
      "layout(std140) uniform B { mat4 m; } b;\n"
      "struct S { float<length> d[2]; };\n"
      "template<dimension D> float<D> twice(float<D> x) { return x + x; }\n"
      "void main() { for (int i = 0; i < 3; ++i) { if (i == 1) continue; } switch (1) { default: break; } }\n";
  std::mt19937 rng(777);
  std::uniform_int_distribution<std::size_t> where(0, shader.size() - 1);
  const char junk[] = "{}()[];<>,=+*x1 ";
  std::uniform_int_distribution<std::size_t> pick(0, sizeof(junk) - 2);
  for (int round = 0; round < 1500; ++round) {
    std::string text = shader;
    for (int k = 0; k < 3; ++k) text[where(rng)] = junk[pick(rng)];
    auto parsed = parse_text(text);
    ASSERT_NE(parsed->result.unit, nullptr);
    (void)parsed->glsl();
  }
}

}  // namespace
}  // namespace safegi::testing
