#include "preprocessor_test_support.hpp"

namespace safegi::testing {
namespace {

using Directives = PreprocessorTest;

TEST_F(Directives, IfdefIfndefElseEndif) {
  EXPECT_EQ(output("#define A\n#ifdef A\na\n#else\nnot_a\n#endif\n#ifndef A\nb\n#else\nnot_b\n#endif\n"),
            "a\nnot_b");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, IfElifChains) {
  const char* chain = "#if X == 1\none\n#elif X == 2\ntwo\n#elif X > 2\nmany\n#else\nnone\n#endif\n";
  EXPECT_EQ(output(std::string("#define X 1\n") + chain), "one");
  EXPECT_EQ(output(std::string("#define X 2\n") + chain), "two");
  EXPECT_EQ(output(std::string("#define X 7\n") + chain), "many");
  EXPECT_EQ(output(std::string("#define X 0\n") + chain), "none");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, NestedConditionalsInSkippedGroups) {
  EXPECT_EQ(output("#if 0\n#if 1\nx\n#else\ny\n#endif\n#elif 1\nz\n#endif\n"), "z");
  EXPECT_EQ(output("#ifdef NOPE\n#bogus directive\n@ $ invalid stuff\n#endif\nok\n"), "ok");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, ElifAfterTakenGroupIsNotEvaluated) {
  EXPECT_EQ(output("#if 1\na\n#elif 1 / 0\nb\n#endif\n"), "a");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, ExpressionOperators) {
  struct Row {
    const char* expression;
    bool value;
  };
  for (Row r : {Row{"1 + 2 * 3 == 7", true}, Row{"(1 + 2) * 3 == 9", true}, Row{"10 / 3 == 3", true},
                Row{"10 % 3 == 1", true}, Row{"-1 < 0", true}, Row{"~0 == -1", true}, Row{"!0", true},
                Row{"!!5 == 1", true}, Row{"1 << 4 == 16", true}, Row{"256 >> 4 == 16", true},
                Row{"(6 & 3) == 2", true}, Row{"(6 | 3) == 7", true}, Row{"(6 ^ 3) == 5", true},
                Row{"2 >= 2 && 2 <= 2 && 1 != 2", true}, Row{"0 || 0", false}, Row{"0x10 == 16", true},
                Row{"010 == 8", true}, Row{"3u == 3", true}, Row{"1 - 2 - 3 == -4", true},
                Row{"+1 == 1", true}, Row{"defined A && defined(B)", true}, Row{"defined C", false},
                Row{"!defined C", true}, Row{"0 && 1 / 0", false}, Row{"1 || 1 % 0", true},
                Row{"A + B == 3", true}, Row{"2147483647 + 1 < 0", true},
                Row{"0xFFFFFFFF == -1", true}, Row{"-2147483648 / -1 == 0", true}, Row{"1 << 31 < 0", true}}) {
    std::string source = std::string("#define A 1\n#define B 2\n#if ") + r.expression + "\nyes\n#else\nno\n#endif\n";
    EXPECT_EQ(output(source), r.value ? "yes" : "no") << r.expression;
  }
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, MacrosInConditions) {
  EXPECT_EQ(output("#define VERSION_AT_LEAST(v) (__VERSION__ >= v)\n#if VERSION_AT_LEAST(110)\nok\n#endif\n"), "ok");
  EXPECT_EQ(output("#version 300 es\n#if defined(GL_ES) && GL_ES == 1\nes\n#endif\n"), "es");
}

TEST_F(Directives, ExpressionErrors) {
  output("#if 1 / 0\n#endif\n#if 5 % (2 - 2)\n#endif\n#if 1.5\n#endif\n#if (1\n#endif\n#if\n#endif\n#if 1 2\n#endif\n"
         "#if 1 << 32\n#endif\n#if 1 +\n#endif\n#if defined\n#endif\n#if true\n#endif\n#if 1 ? 2 : 3\n#endif\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:7: error: division by zero in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 1 / 0\n"
            "      ^\n"
            "main.glsl:3:7: error: remainder by zero in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 5 % (2 - 2)\n"
            "      ^\n"
            "main.glsl:5:5: error: floating-point literal '1.5' in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 1.5\n"
            "    ^~~\n"
            "main.glsl:7:7: error: expected ')' in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if (1\n"
            "      ^\n"
            "main.glsl:9:1: error: expected an expression after the directive [E-PP-EXPRESSION]\n"
            "#if\n"
            "^~~\n"
            "main.glsl:11:7: error: unexpected '2' in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 1 2\n"
            "      ^\n"
            "main.glsl:13:7: error: shift count 32 is out of range [E-PP-EXPRESSION]\n"
            "#if 1 << 32\n"
            "      ^~\n"
            "main.glsl:15:8: error: expected a value at the end of the preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 1 +\n"
            "       ^\n"
            "main.glsl:17:5: error: expected a macro name after 'defined' [E-PP-EXPRESSION]\n"
            "#if defined\n"
            "    ^~~~~~~\n"
            "main.glsl:19:5: error: 'true' is not allowed in a preprocessor expression (use 1 or 0) [E-PP-EXPRESSION]\n"
            "#if true\n"
            "    ^~~~\n"
            "main.glsl:21:7: error: unexpected '?' in preprocessor expression [E-PP-EXPRESSION]\n"
            "#if 1 ? 2 : 3\n"
            "      ^\n");
}

TEST_F(Directives, UndefinedIdentifiersInConditions) {
  EXPECT_EQ(output("#if UNDEFINED_THING\nx\n#else\ny\n#endif\n"), "y");
  EXPECT_EQ(errors(),
            "main.glsl:1:5: warning: 'UNDEFINED_THING' is not defined, evaluates to 0 [W-UNDEFINED-MACRO]\n"
            "#if UNDEFINED_THING\n"
            "    ^~~~~~~~~~~~~~~\n");
  diagnostics.clear();
  output("#version 300 es\n#if UNDEFINED_THING\n#endif\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:5: error: 'UNDEFINED_THING' is not defined (undefined macros are errors in #if in ES) [E-PP-EXPRESSION]\n"
            "#if UNDEFINED_THING\n"
            "    ^~~~~~~~~~~~~~~\n");
}

// glslang's rule (TPpContext::eval's shortCircuit), issue 46: in ES an undefined macro is an
// error unless it follows `&&` after 0 or `||` after exactly 1, on that level of the expression.
TEST_F(Directives, UndefinedIdentifiersInEsConditionsFollowGlslangsShortCircuit) {
  for (const char* quiet : {"defined(X) && X", "!defined(X) || X", "0 && X", "1 || X", "(1) || X", "1 == 1 || X",
                            "0 && (X + 1)", "0 && X || Y", "1 || X && Y", "0 && -X", "1 && (0 && X)"}) {
    diagnostics.clear();
    output(std::string("#version 300 es\n#if ") + quiet + "\n#endif\n");
    EXPECT_EQ(diagnostics.error_count(), 0u) << quiet << "\n" << errors();
  }
  for (const char* loud : {"X && defined(X)", "defined(X) || X", "X", "1 && X", "0 || X", "2 || X",
                           "(defined(X) && X) || X"}) {
    diagnostics.clear();
    output(std::string("#version 300 es\n#if ") + loud + "\n#endif\n");
    EXPECT_EQ(diagnostics.error_count(), 1u) << loud;
    EXPECT_NE(errors().find("'X' is not defined (undefined macros are errors in #if in ES)"), std::string::npos) << loud;
  }
}

TEST_F(Directives, ConditionalStructureErrors) {
  output("#endif\n#else\n#elif 1\n#if 1\n#else\n#else\n#endif\n#ifdef\n#endif\n#ifdef 3\n#endif\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:1: error: #endif without #if [E-CONDITIONAL]\n"
            "#endif\n"
            "^~~~~~\n"
            "main.glsl:2:1: error: #else without #if [E-CONDITIONAL]\n"
            "#else\n"
            "^~~~~\n"
            "main.glsl:3:1: error: #elif without #if [E-CONDITIONAL]\n"
            "#elif 1\n"
            "^~~~~~~\n"
            "main.glsl:6:1: error: #else after #else [E-CONDITIONAL]\n"
            "#else\n"
            "^~~~~\n"
            "main.glsl:4:1: note: the conditional started here\n"
            "#if 1\n"
            "^~~~~\n"
            "main.glsl:8:1: error: macro name missing in #ifdef [E-DIRECTIVE]\n"
            "#ifdef\n"
            "^~~~~~\n"
            "main.glsl:10:8: error: macro name must be an identifier [E-MACRO]\n"
            "#ifdef 3\n"
            "       ^\n");
}

TEST_F(Directives, UnterminatedConditionalIsReportedAtTheIf) {
  output("a\n#if 1\nb\n#ifdef X\nc\n");
  EXPECT_EQ(errors(),
            "main.glsl:4:1: error: unterminated conditional directive [E-CONDITIONAL]\n"
            "#ifdef X\n"
            "^~~~~~~~\n"
            "main.glsl:2:1: error: unterminated conditional directive [E-CONDITIONAL]\n"
            "#if 1\n"
            "^~~~~\n");
}

TEST_F(Directives, Extension) {
  auto unit = run("#version 150\n#extension GL_ARB_tessellation_shader : enable\n#extension all : warn\npatch in;\n");
  ASSERT_EQ(unit.extensions.size(), 2u);
  EXPECT_EQ(unit.extensions[0].name, "GL_ARB_tessellation_shader");
  EXPECT_EQ(unit.extensions[0].behavior, "enable");
  EXPECT_EQ(unit.extensions[1].name, "all");
  EXPECT_EQ(unit.tokens[0].kind, TokenKind::kw_patch);  // the extension made `patch` a keyword
  EXPECT_EQ(errors(), "");
  run("#extension\n#extension GL_X\n#extension GL_X :\n#extension GL_X : maybe\n#extension all : enable\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:1: error: expected an extension name after #extension [E-DIRECTIVE]\n"
            "#extension\n"
            "^~~~~~~~~~\n"
            "main.glsl:2:12: error: expected ':' after the extension name [E-DIRECTIVE]\n"
            "#extension GL_X\n"
            "           ^~~~\n"
            "main.glsl:3:17: error: expected 'require', 'enable', 'warn' or 'disable' after ':' [E-DIRECTIVE]\n"
            "#extension GL_X :\n"
            "                ^\n"
            "main.glsl:4:19: error: unknown extension behavior 'maybe' (expected 'require', 'enable', 'warn' or "
            "'disable') [E-DIRECTIVE]\n"
            "#extension GL_X : maybe\n"
            "                  ^~~~~\n"
            "main.glsl:5:18: error: 'all' can only be used with 'warn' or 'disable' [E-DIRECTIVE]\n"
            "#extension all : enable\n"
            "                 ^~~~~~\n");
}

TEST_F(Directives, Pragma) {
  auto unit = run("#pragma optimize(off)\n#pragma   debug (on)\n#pragma STDGL invariant(all)\n");
  ASSERT_EQ(unit.pragmas.size(), 3u);
  EXPECT_EQ(unit.pragmas[0].text, "optimize(off)");
  EXPECT_EQ(unit.pragmas[1].text, "debug (on)");
  EXPECT_EQ(unit.pragmas[2].text, "STDGL invariant(all)");
  EXPECT_EQ(unit.pragmas[2].range.begin.line, 3u);
}

TEST_F(Directives, Error) {
  auto unit = run("#define X\n#ifdef X\n#error X must not be defined, sorry // why\n#endif\n#error\n");
  EXPECT_EQ(errors(),
            "main.glsl:3:2: error: #error: X must not be defined, sorry [E-ERROR-DIRECTIVE]\n"
            "#error X must not be defined, sorry // why\n"
            " ^~~~~\n"
            "main.glsl:5:2: error: #error [E-ERROR-DIRECTIVE]\n"
            "#error\n"
            " ^~~~~\n");
}

TEST_F(Directives, Line) {
  auto unit = run("#version 330\na\n#line 100\nb __LINE__\n#line 7 3\nc __LINE__ __FILE__\n#define L 50\n#line L\nd __LINE__\n");
  EXPECT_EQ(spell(unit), "a\nb 100\nc 7 3\nd 50");
  ASSERT_EQ(unit.line_directives.size(), 3u);
  EXPECT_EQ(unit.line_directives[1].source_string, 3u);
  // Diagnostics report the presumed line; the quoted source line stays physical.
  diagnostics.error(unit.tokens[3].range, "here");
  EXPECT_EQ(errors(),
            "main.glsl:7:1: error: here\n"
            "c __LINE__ __FILE__\n"
            "^\n");
}

TEST_F(Directives, LineBefore330NamesTheDirectivesOwnLine) {
  EXPECT_EQ(output("#version 150\n#line 3000\n__LINE__\n"), "3001");
  EXPECT_EQ(output("#version 100\n#line 3000\n__LINE__\n"), "3000");
}

TEST_F(Directives, LineWithFileName) {
  auto unit = run("#version 450\n#line 10 \"generated.glsl\"\nx\n");
  diagnostics.error(unit.tokens[0].range, "e");
  EXPECT_EQ(errors(),
            "generated.glsl:10:1: error: e\n"
            "x\n"
            "^\n");
}

TEST_F(Directives, FileFollowsTheLastLineDirective) {
  // GL_GOOGLE_cpp_style_line_directive: a name replaces the source-string
  // number until the next `#line N S`; a bare `#line N` keeps either.
  EXPECT_EQ(output("#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : enable\n"
                   "#extension GL_EXT_debug_printf : enable\n__FILE__\n#line 150 \"a.h\"\n__FILE__\n"
                   "#line 24\n__FILE__\n#line 10 3\n__FILE__\n#line 48\n__FILE__\n"),
            "0\n\"a.h\"\n\"a.h\"\n3\n3");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, LineErrors) {
  run("#line\n#line x\n#line 1 y\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:1: error: expected a line number after #line [E-DIRECTIVE]\n"
            "#line\n"
            "^~~~~\n"
            "main.glsl:2:7: error: expected a line number after #line [E-DIRECTIVE]\n"
            "#line x\n"
            "      ^\n"
            "main.glsl:3:9: error: expected a source-string number or a file name after the line number [E-DIRECTIVE]\n"
            "#line 1 y\n"
            "        ^\n");
}

TEST_F(Directives, UnknownDirective) {
  run("#foo bar\n# 12\n#\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:2: error: invalid preprocessing directive '#foo' [E-DIRECTIVE]\n"
            "#foo bar\n"
            " ^~~\n"
            "main.glsl:2:3: error: invalid preprocessing directive '#12' [E-DIRECTIVE]\n"
            "# 12\n"
            "  ^~\n");
}

TEST_F(Directives, HashOutsideDirectivesAndStrings) {
  run("a # b\n\"str\"\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:3: error: '#' is only allowed at the start of a directive line [E-CHARACTER]\n"
            "a # b\n"
            "  ^\n"
            "main.glsl:2:1: error: string literals are not allowed in GLSL [E-CHARACTER]\n"
            "\"str\"\n"
            "^~~~~\n");
}

TEST_F(Directives, NumbersAreCheckedWhereTheyAreUsed) {
  EXPECT_EQ(output("#define SUFFIX 1D\n#if 0\n3.5L 09 0x\n#endif\nfloat x = 1.0;\n"), "float x = 1.0 ;");
  EXPECT_EQ(errors(), "");
  output("#define SUFFIX 1D\nSUFFIX\n#if 1D\n#endif\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:17: error: invalid suffix 'D' on integer literal [E-LITERAL]\n"
            "#define SUFFIX 1D\n"
            "                ^\n"
            "main.glsl:2:1: note: in expansion of macro 'SUFFIX' (defined at main.glsl:1:9)\n"
            "SUFFIX\n"
            "^~~~~~\n"
            "main.glsl:3:5: error: invalid suffix 'D' on integer literal [E-LITERAL]\n"
            "#if 1D\n"
            "    ^~\n");
}

TEST_F(Directives, InvalidCharactersAreReportedWhereUsed) {
  EXPECT_EQ(output("#version 300 es\n#define eat_sushi \xE7\xAE\xB8\n#if 0\n@\n#endif\nok\n"), "ok");
  EXPECT_EQ(errors(), "");
  output("#define AT @\nAT\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:12: error: invalid character '@' in program [E-CHARACTER]\n"
            "#define AT @\n"
            "           ^\n"
            "main.glsl:2:1: note: in expansion of macro 'AT' (defined at main.glsl:1:9)\n"
            "AT\n"
            "^~\n");
}

TEST_F(Directives, StringsWithDebugPrintf) {
  auto unit = run("#version 450\n#extension GL_EXT_debug_printf : enable\ndebugPrintfEXT(\"x = %f\", x);\n");
  EXPECT_EQ(unit.tokens[2].kind, TokenKind::string_literal);
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, ExtensionMacros) {
  options.extension_macros = {"GL_ARB_gpu_shader5"};
  options.reject_unsupported_extensions = true;
  EXPECT_EQ(output("#ifdef GL_ARB_gpu_shader5\nyes GL_ARB_gpu_shader5\n#endif\n"), "yes 1");
  EXPECT_EQ(errors(), "");
  run("#extension GL_ARB_gpu_shader5 : require\n#extension GL_FOO_bar : require\n#extension GL_FOO_baz : enable\n"
      "#extension GL_FOO_baz : disable\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:12: error: extension 'GL_FOO_bar' is not supported [E-EXTENSION]\n"
            "#extension GL_FOO_bar : require\n"
            "           ^~~~~~~~~~\n"
            "main.glsl:3:12: warning: extension 'GL_FOO_baz' is not supported [W-EXTENSION]\n"
            "#extension GL_FOO_baz : enable\n"
            "           ^~~~~~~~~~\n");
}

TEST_F(Directives, KnownExtensionsArePredefinedByDefault) {
  EXPECT_EQ(output("#version 150\n#if GL_ARB_gpu_shader5 && defined(GL_ARB_fragment_coord_conventions)\nyes\n#endif\n"
                   "#ifdef GL_NV_cooperative_matrix\nno\n#endif\n#ifdef GL_EXT_control_flow_attributes\nattributes\n#endif\n"),
            "yes\nattributes");
  // Not strict by default: an extension the front end does not know is
  // accepted without a macro (the type checker judges its built-ins), with a
  // warning when glslang does not know it either.
  run("#extension GL_FOO_bar : require\n#undef GL_ARB_gpu_shader5\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:12: warning: unknown extension 'GL_FOO_bar': it turns nothing on [W-UNKNOWN-EXTENSION]\n"
            "#extension GL_FOO_bar : require\n"
            "           ^~~~~~~~~~\n"
            "help: glslangValidator refuses a shader that requires an extension it does not know\n"
            "main.glsl:2:8: error: cannot undefine predefined macro 'GL_ARB_gpu_shader5' [E-MACRO]\n"
            "#undef GL_ARB_gpu_shader5\n"
            "       ^~~~~~~~~~~~~~~~~~\n");
}

TEST_F(Directives, AnExtensionNeitherGlslangNorWeKnowIsWarnedAbout) {
  // glslang knows GL_NV_cooperative_matrix (this front end does not parse it): no warning,
  // as glslangValidator gives none; a misspelt name gets glslangValidator's warning.
  run("#extension GL_NV_cooperative_matrix : enable\n#extension GL_EXT_ray_tracing : require\n"
      "#extension GL_EXT_raytracing : require\n#extension GL_FOO_bar : enable\n#extension GL_FOO_bar : disable\n");
  EXPECT_EQ(errors(),
            "main.glsl:3:12: warning: unknown extension 'GL_EXT_raytracing': it turns nothing on [W-UNKNOWN-EXTENSION]\n"
            "#extension GL_EXT_raytracing : require\n"
            "           ^~~~~~~~~~~~~~~~~\n"
            "help: glslangValidator refuses a shader that requires an extension it does not know\n"
            "main.glsl:4:12: warning: unknown extension 'GL_FOO_bar': it turns nothing on [W-UNKNOWN-EXTENSION]\n"
            "#extension GL_FOO_bar : enable\n"
            "           ^~~~~~~~~~\n");
  EXPECT_TRUE(glslang_knows_extension("GL_KHR_shader_subgroup_basic"));
  EXPECT_FALSE(glslang_knows_extension("GL_KHR_shader_subgroup_basics"));
}

TEST_F(Directives, ExtensionsEnableKeywordsAtOlderVersions) {
  auto unit = run("#version 150\n#extension GL_ARB_shader_subroutine : require\n"
                  "#extension GL_ARB_shader_storage_buffer_object : enable\n#extension GL_EXT_gpu_shader4 : enable\n"
                  "#extension GL_AMD_conservative_depth : enable\nsubroutine coherent flat layout\n");
  ASSERT_GE(unit.tokens.size(), 4u);
  EXPECT_EQ(unit.tokens[0].kind, TokenKind::kw_subroutine);
  EXPECT_EQ(unit.tokens[1].kind, TokenKind::kw_coherent);
  EXPECT_EQ(unit.tokens[2].kind, TokenKind::kw_flat);
  EXPECT_EQ(unit.tokens[3].kind, TokenKind::kw_layout);
  EXPECT_EQ(unit.language.version, 150);
  EXPECT_TRUE(unit.language.extension_enabled("GL_EXT_gpu_shader4"));
  auto shader4 = run("#extension GL_EXT_gpu_shader4 : require\ncentroid varying unsigned int u; uvec2 v;\n");
  EXPECT_EQ(spell(shader4), "centroid varying uint u ; uvec2 v ;");
  EXPECT_EQ(shader4.tokens[0].kind, TokenKind::kw_centroid);
  EXPECT_EQ(shader4.tokens[2].kind, TokenKind::kw_uint);
  EXPECT_EQ(shader4.tokens[2].range, sources.range_of(shader4.tokens[2].range.begin.file, 57, 69));
  EXPECT_EQ(shader4.tokens[5].kind, TokenKind::kw_uvec2);
  auto plain = run("#version 130\nsubroutine coherent layout\n");
  EXPECT_EQ(plain.tokens[0].kind, TokenKind::identifier);
  EXPECT_EQ(plain.tokens[1].kind, TokenKind::identifier);
  EXPECT_EQ(plain.tokens[2].kind, TokenKind::identifier);
}

TEST_F(Directives, DoubleLiteralsNeedVersion400OrFp64) {
  output("#version 330\ndouble d = 1.0lf;\n#extension GL_ARB_gpu_shader_fp64 : enable\ndouble e = 2.0LF;\n");
  output("#version 310 es\nx = 1.0lf;\n");
  output("#version 400\ndouble d = 1.0lf;\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:12: error: double-precision literals ('lf' suffix) require #version 400 or "
            "GL_ARB_gpu_shader_fp64 [E-VERSION]\n"
            "double d = 1.0lf;\n"
            "           ^~~~~\n"
            "main.glsl:2:5: error: double-precision literals ('lf' suffix) are not available in GLSL ES (without "
            "GL_ARB_gpu_shader_fp64) [E-VERSION]\n"
            "x = 1.0lf;\n"
            "    ^~~~~\n");
}

TEST_F(Directives, PasteAtAnEndOfTheBodyWarnsAndErrsWhenUsed) {
  EXPECT_EQ(output("#define UNUSED(arg) x ##\nok\n"), "ok");
  EXPECT_FALSE(diagnostics.has_errors());
  output("#define P(a) a ##\nP(1)\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:23: warning: '##' cannot appear at either end of a macro body [W-MACRO]\n"
            "#define UNUSED(arg) x ##\n"
            "                      ^~\n"
            "help: using this macro is an error\n"
            "main.glsl:1:16: warning: '##' cannot appear at either end of a macro body [W-MACRO]\n"
            "#define P(a) a ##\n"
            "               ^~\n"
            "help: using this macro is an error\n"
            "main.glsl:2:1: error: macro 'P' cannot be used: '##' at an end of its body [E-MACRO]\n"
            "P(1)\n"
            "^~~~\n"
            "main.glsl:1:16: note: '##' is here\n"
            "#define P(a) a ##\n"
            "               ^~\n");
}

TEST_F(Directives, PastingAKeywordFromAnExpandedArgument) {
  // cppMerge.frag of glslang's tests: the argument is expanded before the
  // inner macro pastes it, and the pasted word is classified as a keyword.
  auto unit = run("#version 450\n#define PASTE(a, b) a##b\n#define MAKE(a, b) PASTE(a, b)\n#define PREFIX image\n"
                  "#define SUFFIX 1D\nMAKE(PREFIX, SUFFIX) MAKE(imag, e1D)\n");
  EXPECT_EQ(spell(unit), "image1D image1D");
  EXPECT_EQ(unit.tokens[0].kind, TokenKind::kw_image1D);
  EXPECT_EQ(unit.tokens[1].kind, TokenKind::kw_image1D);
  // As in C, pasting joins two tokens only: `imag ## e1 D` is `image1 D`
  // (glslang glues the D on too; docs/frontend-corpus.md).
  EXPECT_EQ(output("#define PASTE(a, b) a##b\nPASTE(imag, e1 D)\n"), "image1 D");
  EXPECT_EQ(errors(), "");
}

TEST_F(Directives, DirectiveLinesAndSkippedRangesAreRecorded) {
  auto unit = run("#version 330\n#define A \\\n  1\nx\n#if 0\nskipped\n#endif // done\n");
  ASSERT_EQ(unit.directives.size(), 4u);
  EXPECT_EQ(unit.directives[0].kind, DirectiveKind::version);
  EXPECT_EQ(unit.directives[1].kind, DirectiveKind::define);
  EXPECT_EQ(unit.directives[1].range, sources.range_of(main, 13, 28));  // through the continued line
  EXPECT_EQ(unit.directives[2].kind, DirectiveKind::if_);
  EXPECT_EQ(unit.directives[3].kind, DirectiveKind::endif);
  EXPECT_EQ(unit.directives[3].range.end.offset, 59u);  // the trailing comment is part of the line
  ASSERT_EQ(unit.skipped_ranges.size(), 1u);
  EXPECT_EQ(sources.text(main).substr(unit.skipped_ranges[0].begin.offset, unit.skipped_ranges[0].length()),
            "skipped\n");
}

}  // namespace
}  // namespace safegi::testing
