#include <safegi/diagnostics/render.hpp>

#include <gtest/gtest.h>

namespace safegi {
namespace {

class RenderText : public ::testing::Test {
 protected:
  FileId add(std::string path, std::string text) { return sm.add_file(std::move(path), std::move(text)); }
  SourceRange range(FileId f, std::uint32_t b, std::uint32_t e) { return sm.range_of(f, b, e); }
  SourceManager sm;
};

TEST_F(RenderText, CaretAndRange) {
  FileId f = add("a.glsl", "void main() {\n  float x = a + bb;\n}\n");
  Diagnostic d = Diagnostic::error(range(f, 30, 32), "undeclared identifier 'bb'");
  EXPECT_EQ(render_text(d, sm),
            "a.glsl:2:17: error: undeclared identifier 'bb'\n"
            "  float x = a + bb;\n"
            "                ^~\n");
}

TEST_F(RenderText, HighlightsHintCodeAndNotes) {
  FileId f = add("a.glsl", "float<length> d = t * 2.0;\nfloat<time> t;\n");
  Diagnostic d = Diagnostic::error(range(f, 16, 17), "cannot initialize 'float<length>' with 'float<time>'")
                     .with_highlight(range(f, 18, 25))
                     .with_code("E-DIM-MISMATCH")
                     .with_hint("multiply by a velocity")
                     .with_note(Diagnostic::note(range(f, 39, 40), "'t' declared here"));
  EXPECT_EQ(render_text(d, sm),
            "a.glsl:1:17: error: cannot initialize 'float<length>' with 'float<time>' [E-DIM-MISMATCH]\n"
            "float<length> d = t * 2.0;\n"
            "                ^ ~~~~~~~\n"
            "help: multiply by a velocity\n"
            "a.glsl:2:13: note: 't' declared here\n"
            "float<time> t;\n"
            "            ^\n");
}

TEST_F(RenderText, TabsExpandToTabStops) {
  FileId f = add("t.glsl", "\tx\t= y;\n");
  EXPECT_EQ(render_text(Diagnostic::warning(range(f, 3, 4), "w"), sm),
            "t.glsl:1:4: warning: w\n"
            "    x   = y;\n"
            "        ^\n");
}

TEST_F(RenderText, RangeRunningPastTheLineIsCutAtItsEnd) {
  FileId f = add("a.glsl", "/* open\nmore");
  EXPECT_EQ(render_text(Diagnostic::error(range(f, 0, 12), "unterminated comment"), sm),
            "a.glsl:1:1: error: unterminated comment\n"
            "/* open\n"
            "^~~~~~~\n");
}

TEST_F(RenderText, LocationAtEndOfFile) {
  FileId f = add("a.glsl", "x");
  EXPECT_EQ(render_text(Diagnostic::error(range(f, 1, 1), "expected ';'"), sm),
            "a.glsl:1:2: error: expected ';'\n"
            "x\n"
            " ^\n");
}

TEST_F(RenderText, NoLocation) {
  EXPECT_EQ(render_text(Diagnostic::error({}, "no input files"), sm), "error: no input files\n");
}

TEST_F(RenderText, IncludeChain) {
  FileId main = add("main.glsl", "#version 330\n#include \"a.glsl\"\n");
  FileId a = add("a.glsl", "#include \"b.glsl\"\n");
  FileId b = add("b.glsl", "bad\n");
  sm.set_included_from(a, range(main, 13, 30));
  sm.set_included_from(b, range(a, 0, 17));
  EXPECT_EQ(render_text(Diagnostic::error(range(b, 0, 3), "bad"), sm),
            "In file included from main.glsl:2:1:\n"
            "In file included from a.glsl:1:1:\n"
            "b.glsl:1:1: error: bad\n"
            "bad\n"
            "^~~\n");
}

TEST_F(RenderText, MacroExpansionChain) {
  FileId f = add("m.glsl", "#define INNER (y + 1)\n#define OUTER(a) (a * INNER)\nfloat z = OUTER(2);\n");
  ExpansionId outer = sm.add_expansion({"OUTER", range(f, 30, 35), range(f, 61, 69), kNoExpansion});
  ExpansionId inner = sm.add_expansion({"INNER", range(f, 8, 13), range(f, 44, 49), outer});
  Diagnostic d = Diagnostic::error(range(f, 15, 16), "undeclared identifier 'y'").with_expansion(inner);
  EXPECT_EQ(render_text(d, sm),
            "m.glsl:1:16: error: undeclared identifier 'y'\n"
            "#define INNER (y + 1)\n"
            "               ^\n"
            "m.glsl:2:23: note: in expansion of macro 'INNER' (defined at m.glsl:1:9)\n"
            "#define OUTER(a) (a * INNER)\n"
            "                      ^~~~~\n"
            "m.glsl:3:11: note: in expansion of macro 'OUTER' (defined at m.glsl:2:9)\n"
            "float z = OUTER(2);\n"
            "          ^~~~~~~~\n");
}

TEST_F(RenderText, LineDirectiveChangesTheHeaderOnly) {
  FileId f = add("a.glsl", "#line 100 \"gen.glsl\"\nx;\n");
  sm.add_line_directive(f, 21, 100, std::string("gen.glsl"), std::nullopt);
  EXPECT_EQ(render_text(Diagnostic::error(range(f, 21, 22), "e"), sm),
            "gen.glsl:100:1: error: e\n"
            "x;\n"
            "^\n");
}

TEST_F(RenderText, ColourOnlyWhenAsked) {
  FileId f = add("a.glsl", "x\n");
  std::string plain = render_text(Diagnostic::error(range(f, 0, 1), "e"), sm);
  std::string coloured = render_text(Diagnostic::error(range(f, 0, 1), "e"), sm, TextStyle{.color = true});
  EXPECT_EQ(plain.find('\x1b'), std::string::npos);
  EXPECT_EQ(coloured,
            "\x1b[1ma.glsl:1:1: \x1b[1;31merror: \x1b[0m\x1b[1me\x1b[0m\n"
            "x\n"
            "\x1b[1;32m^\x1b[0m\n");
}

TEST_F(RenderText, Utf8InCommentsTakesOneColumnPerCharacter) {
  FileId f = add("u.glsl", "// \xC3\xA9t\xC3\xA9\nx y\n");
  EXPECT_EQ(render_text(Diagnostic::error(range(f, 3, 8), "e"), sm),
            "u.glsl:1:4: error: e\n"
            "// \xC3\xA9t\xC3\xA9\n"
            "   ^~~\n");
}

}  // namespace
}  // namespace safegi
