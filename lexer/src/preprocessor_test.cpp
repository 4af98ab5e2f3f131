#include "preprocessor_test_support.hpp"

namespace safegi::testing {
namespace {

using Preprocess = PreprocessorTest;

TEST_F(Preprocess, PlainTokensPassThroughClassified) {
  auto unit = run("#version 330 core\nfloat x = 1.0;\nvec3 sample;\n");
  EXPECT_EQ(spell(unit), "float x = 1.0 ;\nvec3 sample ;");
  EXPECT_EQ(unit.tokens[0].kind, TokenKind::kw_float);
  EXPECT_EQ(unit.tokens[5].kind, TokenKind::kw_vec3);
  EXPECT_EQ(unit.tokens[6].kind, TokenKind::identifier);  // `sample` is a keyword only from 400
  EXPECT_EQ(unit.tokens.back().kind, TokenKind::eof);
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, Version) {
  auto unit = run("// leading comment\n\n#version 310 es\nprecision highp float;\n");
  EXPECT_EQ(unit.version, 310);
  EXPECT_EQ(unit.profile, "es");
  EXPECT_TRUE(unit.es);
  EXPECT_TRUE(unit.version_given);
  EXPECT_EQ(unit.version_range.begin.line, 3u);
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, VersionDefaultsTo110) {
  auto unit = run("void main() {}\n");
  EXPECT_EQ(unit.version, 110);
  EXPECT_FALSE(unit.version_given);
  EXPECT_EQ(unit.profile, "");
}

TEST_F(Preprocess, VersionMustComeFirst) {
  run("float x;\n#version 330\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:1: error: #version must come first in a shader, before anything but comments and white space [E-VERSION-DIRECTIVE]\n"
            "#version 330\n"
            "^~~~~~~~~~~~\n");
}

TEST_F(Preprocess, VersionErrors) {
  run("#version 331\n");
  run("#version 300\n");
  run("#version 330 es\n");
  run("#version 120 core\n");
  run("#version 450 foo\n");
  run("#version\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:10: error: unknown GLSL version 331 (expected 100, 110 ... 150, 300, 310, 320, or 330 ... 460) [E-VERSION-DIRECTIVE]\n"
            "#version 331\n"
            "         ^~~\n"
            "main.glsl:1:1: error: #version 300 requires the 'es' profile [E-VERSION-DIRECTIVE]\n"
            "#version 300\n"
            "^~~~~~~~~~~~\n"
            "main.glsl:1:14: error: the 'es' profile requires version 300, 310 or 320 [E-VERSION-DIRECTIVE]\n"
            "#version 330 es\n"
            "             ^~\n"
            "main.glsl:1:14: error: profiles are only allowed from #version 150 on [E-VERSION-DIRECTIVE]\n"
            "#version 120 core\n"
            "             ^~~~\n"
            "main.glsl:1:14: error: unknown profile 'foo' (expected 'core', 'compatibility' or 'es') [E-VERSION-DIRECTIVE]\n"
            "#version 450 foo\n"
            "             ^~~\n"
            "main.glsl:1:1: error: expected a version number after #version [E-VERSION-DIRECTIVE]\n"
            "#version\n"
            "^~~~~~~~\n");
}

TEST_F(Preprocess, VersionTwice) {
  run("#version 330\n#version 330\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:1: error: #version may appear only once [E-VERSION-DIRECTIVE]\n"
            "#version 330\n"
            "^~~~~~~~~~~~\n"
            "main.glsl:1:1: note: first #version is here\n"
            "#version 330\n"
            "^~~~~~~~~~~~\n");
}

TEST_F(Preprocess, PredefinedMacros) {
  EXPECT_EQ(output("#version 450\n__VERSION__ GL_core_profile __LINE__\n__LINE__ __FILE__\n"), "450 1 2\n3 0");
  EXPECT_EQ(output("#version 300 es\nGL_ES GL_es_profile GL_FRAGMENT_PRECISION_HIGH __VERSION__\n"), "1 1 1 300");
  EXPECT_EQ(output("#version 150 compatibility\nGL_compatibility_profile GL_core_profile\n"), "1 GL_core_profile");
  EXPECT_EQ(output("#version 130\nGL_FRAGMENT_PRECISION_HIGH\n"), "1");
  EXPECT_EQ(output("#version 120\nGL_FRAGMENT_PRECISION_HIGH\n"), "GL_FRAGMENT_PRECISION_HIGH");
  EXPECT_EQ(output("#ifdef GL_ES\nes\n#else\ndesktop\n#endif\n"), "desktop");
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, ObjectLikeMacros) {
  EXPECT_EQ(output("#define N 4\n#define TWO_N (N * 2)\nfloat a[TWO_N];\n"), "float a [ ( 4 * 2 ) ] ;");
  EXPECT_EQ(output("#define EMPTY\nEMPTY x EMPTY\n"), "x");
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, FunctionLikeMacros) {
  EXPECT_EQ(output("#define SQ(x) ((x) * (x))\nSQ(a + 1)\n"), "( ( a + 1 ) * ( a + 1 ) )");
  EXPECT_EQ(output("#define MAX(a, b) ((a) > (b) ? (a) : (b))\nMAX(f(1, 2), y)\n"),
            "( ( f ( 1 , 2 ) ) > ( y ) ? ( f ( 1 , 2 ) ) : ( y ) )");
  EXPECT_EQ(output("#define F() 7\nF() F ( )\n"), "7 7");
  EXPECT_EQ(output("#define F(x) [x]\nF()\n"), "[ ]");
  EXPECT_EQ(output("#define F(x) x\nF\nfloat F;\n"), "F\nfloat F ;");  // no '(' : not an invocation
  EXPECT_EQ(output("#define F(x) <x>\nF(\n  1\n)\n"), "< 1 >");
  EXPECT_EQ(output("#define F (x) x\nF\n"), "( x ) x");  // space before '(' : object-like
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, NestedAndRecursiveMacros) {
  EXPECT_EQ(output("#define A B\n#define B A\nA B\n"), "A B");
  EXPECT_EQ(output("#define f(x) x + f(x)\nf(1)\n"), "1 + f ( 1 )");
  EXPECT_EQ(output("#define g(x) x\n#define h g(h)\nh\n"), "h");
  EXPECT_EQ(output("#define id(x) x\n#define two 2\nid(id(two))\n"), "2");
  EXPECT_EQ(output("#define f(x) x\n#define g f\ng(3)\n"), "3");
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, TokenPasting) {
  EXPECT_EQ(output("#define CAT(a, b) a ## b\nCAT(vec, 3) CAT(x, ) CAT(, y) CAT(1, 2u)\n"), "vec3 x y 12u");
  auto unit = run("#define CAT(a, b) a##b\nCAT(flo, at) f;\n");
  EXPECT_EQ(unit.tokens[0].kind, TokenKind::kw_float);
  EXPECT_EQ(output("#define V(n) vec ## n\n#define N 4\nV(N)\n"), "vecN");  // operands are not expanded
  EXPECT_EQ(output("#define CAT3(a, b, c) a ## b ## c\nCAT3(x, y, z)\n"), "xyz");
  EXPECT_EQ(output("#define PLUSEQ + ## =\nPLUSEQ\n"), "+=");
  // The pasted token is rescanned: macro expansion happens after pasting.
  EXPECT_EQ(output("#define I i\n#define N n\n#define T t\n#define INT invalid_type\n#define IT I ## N ## T\nIT x;\n"),
            "invalid_type x ;");
  EXPECT_EQ(errors(), "");
}

TEST_F(Preprocess, PastingErrors) {
  output("#define CAT(a, b) a ## b\nCAT(+, -)\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:21: error: pasting '+' and '-' does not give a valid token [E-MACRO]\n"
            "#define CAT(a, b) a ## b\n"
            "                    ^~\n"
            "main.glsl:2:1: note: in expansion of macro 'CAT' (defined at main.glsl:1:9)\n"
            "CAT(+, -)\n"
            "^~~~~~~~~\n");
}

TEST_F(Preprocess, MacroDefinitionErrors) {
  output("#define\n#define 3\n#define F(a, a) a\n#define G(a b) a\n#define H(a, ) a\n#define S(x) #x\n"
         "#define P ## x\n#define defined 1\n#define GL_FOO 1\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:1: error: macro name missing in #define [E-DIRECTIVE]\n"
            "#define\n"
            "^~~~~~~\n"
            "main.glsl:2:9: error: macro name must be an identifier [E-MACRO]\n"
            "#define 3\n"
            "        ^\n"
            "main.glsl:3:14: error: duplicate macro parameter 'a' [E-MACRO]\n"
            "#define F(a, a) a\n"
            "             ^\n"
            "main.glsl:4:13: error: expected ',' or ')' in macro parameter list [E-MACRO]\n"
            "#define G(a b) a\n"
            "            ^\n"
            "main.glsl:5:14: error: expected a parameter name in macro parameter list [E-MACRO]\n"
            "#define H(a, ) a\n"
            "             ^\n"
            "main.glsl:6:14: error: '#' is not allowed in a macro body [E-MACRO]\n"
            "#define S(x) #x\n"
            "             ^\n"
            "help: GLSL has no stringizing operator; only '##' (token pasting) is supported\n"
            "main.glsl:7:11: warning: '##' cannot appear at either end of a macro body [W-MACRO]\n"
            "#define P ## x\n"
            "          ^~\n"
            "help: using this macro is an error\n"
            "main.glsl:8:9: error: 'defined' cannot be used as a macro name [E-MACRO]\n"
            "#define defined 1\n"
            "        ^~~~~~~\n"
            "main.glsl:9:9: error: macro names beginning with 'GL_' are reserved [E-MACRO]\n"
            "#define GL_FOO 1\n"
            "        ^~~~~~\n");
}

TEST_F(Preprocess, DoubleUnderscoreNamesWarn) {
  EXPECT_EQ(output("#define MY__NAME 1\nMY__NAME\n"), "1");
  EXPECT_EQ(errors(),
            "main.glsl:1:9: warning: macro names containing '__' are reserved [W-MACRO]\n"
            "#define MY__NAME 1\n"
            "        ^~~~~~~~\n");
}

TEST_F(Preprocess, Redefinition) {
  output("#define A 1 + 2\n#define A 1 + 2\n#define A 1+2\n#define F(x) x\n#define F(y) y\n");
  EXPECT_EQ(errors(),
            "main.glsl:3:9: error: 'A' macro redefined [E-MACRO]\n"
            "#define A 1+2\n"
            "        ^\n"
            "main.glsl:1:9: note: previous definition is here\n"
            "#define A 1 + 2\n"
            "        ^\n"
            "main.glsl:5:9: error: 'F' macro redefined [E-MACRO]\n"
            "#define F(y) y\n"
            "        ^\n"
            "main.glsl:4:9: note: previous definition is here\n"
            "#define F(x) x\n"
            "        ^\n");
}

TEST_F(Preprocess, PredefinedMacrosCannotChange) {
  output("#version 300 es\n#define __LINE__ 3\n#undef GL_ES\n#undef __VERSION__\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:9: error: cannot redefine predefined macro '__LINE__' [E-MACRO]\n"
            "#define __LINE__ 3\n"
            "        ^~~~~~~~\n"
            "main.glsl:3:8: error: cannot undefine predefined macro 'GL_ES' [E-MACRO]\n"
            "#undef GL_ES\n"
            "       ^~~~~\n"
            "main.glsl:4:8: error: cannot undefine predefined macro '__VERSION__' [E-MACRO]\n"
            "#undef __VERSION__\n"
            "       ^~~~~~~~~~~\n");
}

TEST_F(Preprocess, Undef) {
  EXPECT_EQ(output("#define A 1\nA\n#undef A\nA\n#undef NEVER_DEFINED\n"), "1\nA");
  output("#undef\n#undef X Y\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:1: error: macro name missing in #undef [E-DIRECTIVE]\n"
            "#undef\n"
            "^~~~~~\n"
            "main.glsl:2:10: warning: extra tokens at end of #undef directive [W-EXTRA-TOKENS]\n"
            "#undef X Y\n"
            "         ^\n");
}

TEST_F(Preprocess, ArgumentCountErrors) {
  output("#define F(a, b) a b\nF(1)\nF(1, 2, 3)\n#define G() 0\nG(1)\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:1: error: macro 'F' expects 2 arguments, but 1 was given [E-MACRO]\n"
            "F(1)\n"
            "^~~~\n"
            "main.glsl:3:1: error: macro 'F' expects 2 arguments, but 3 were given [E-MACRO]\n"
            "F(1, 2, 3)\n"
            "^~~~~~~~~~\n"
            "main.glsl:5:1: error: macro 'G' expects 0 arguments, but 1 was given [E-MACRO]\n"
            "G(1)\n"
            "^~~~\n");
}

TEST_F(Preprocess, UnterminatedInvocation) {
  output("#define F(a) a\nF(1, \n");
  EXPECT_EQ(errors(),
            "main.glsl:2:1: error: unterminated argument list invoking macro 'F' [E-MACRO]\n"
            "F(1, \n"
            "^\n");
}

TEST_F(Preprocess, CommasInsideParenthesesStayInOneArgument) {
  EXPECT_EQ(output("#define ONE(a) [a]\nONE((1, 2))\nONE(f(1, 2))\n"), "[ ( 1 , 2 ) ]\n[ f ( 1 , 2 ) ]");
}

TEST_F(Preprocess, CommandLineDefines) {
  options.defines = {{"N", "3"}, {"EMPTY", ""}, {"F(x)", "x*2"}, {"GL_SPECIAL", "1"}};
  options.undefines = {"N"};
  EXPECT_EQ(output("N EMPTY F(4) GL_SPECIAL\n"), "N 4 * 2 1");
  EXPECT_EQ(errors(), "");
}

}  // namespace
}  // namespace safegi::testing
