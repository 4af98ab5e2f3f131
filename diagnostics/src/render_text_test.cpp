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

TEST_F(RenderText, ControlBytesAreEscapedAndTheCaretStaysUnderItsCharacter) {
  using namespace std::string_literals;
  FileId f = add("e\x1b[2J.pbrt", "\x1b[31mShape \0\"x\" bad\n"s);
  Diagnostic d = Diagnostic::error(range(f, 16, 19), "unknown \x1b[1mword").with_hint("h\x07");
  EXPECT_EQ(render_text(d, sm),
            "e\\x1B[2J.pbrt:1:17: error: unknown \\x1B[1mword\n"
            "\\x1B[31mShape \\x00\"x\" bad\n"
            "                      ^~~\n"
            "help: h\\x07\n");
  // An escaped byte takes four columns, and a range over it underlines all four.
  EXPECT_EQ(render_text(Diagnostic::error(range(f, 10, 12), "e"), sm),
            "e\\x1B[2J.pbrt:1:11: error: e\n"
            "\\x1B[31mShape \\x00\"x\" bad\n"
            "             ^~~~~\n");
}

// A long line is cut to a window around the caret, "..." marking what was left out.
class RenderLongLine : public RenderText {
 protected:
  std::string render(std::uint32_t begin, std::uint32_t end, std::size_t columns = 20) {
    return render_text(Diagnostic::error(range(file, begin, end), "e"), sm, TextStyle{.max_line_columns = columns});
  }
  FileId file = add("l.txt", "abcdefghijklmnopqrstuvwxyz0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ\n");
};

TEST_F(RenderLongLine, CutOnBothSidesAroundTheCaret) {
  EXPECT_EQ(render(30, 33),
            "l.txt:1:31: error: e\n"
            "...z0123456789ABC...\n"  // 14 columns of text: 20 less two "..."
            "        ^~~\n");
}

TEST_F(RenderLongLine, CutOnOneSideGivesTheOtherSideItsRoom) {
  EXPECT_EQ(render(2, 3),
            "l.txt:1:3: error: e\n"
            "abcdefghijklmnopq...\n"
            "  ^\n");
  EXPECT_EQ(render(61, 62),
            "l.txt:1:62: error: e\n"
            "...JKLMNOPQRSTUVWXYZ\n"
            "                   ^\n");
  EXPECT_EQ(render(62, 62),  // at the end of the line
            "l.txt:1:63: error: e\n"
            "...KLMNOPQRSTUVWXYZ\n"
            "                   ^\n");
}

TEST_F(RenderLongLine, AnUnderlineWiderThanTheWindowKeepsItsStart) {
  EXPECT_EQ(render(10, 50),
            "l.txt:1:11: error: e\n"
            "...klmnopqrstuvwx...\n"
            "   ^~~~~~~~~~~~~~\n");
}

TEST_F(RenderLongLine, NoCutUnlessWider) {
  EXPECT_EQ(render(30, 31, 62),
            "l.txt:1:31: error: e\n"
            "abcdefghijklmnopqrstuvwxyz0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ\n"
            "                              ^\n");
  EXPECT_EQ(render(30, 31, 0), render(30, 31, 62));  // 0: never cut
}

TEST_F(RenderLongLine, CutsBetweenCharactersOfUtf8EscapesAndTabs) {
  // Columns: 0-3 "\x01", 4 'é', 5-7 the tab's spaces, 8.. "abc…".
  FileId f = add("u.txt", "\x01\xC3\xA9\tabcdefghijklmnopqrstuvwxyz\xE2\x82\xAC" "0123456789\n");
  auto render_in = [&](std::uint32_t begin, std::size_t columns) {
    return render_text(Diagnostic::error(range(f, begin, begin + 1), "e"), sm, TextStyle{.max_line_columns = columns});
  };
  EXPECT_EQ(render_in(3, 16),  // the window would start inside "\x01": it starts after it
            "u.txt:1:4: error: e\n"
            "...\xC3\xA9   abcd...\n"
            "    ^~~\n");
  EXPECT_EQ(render_in(30, 16),  // '€' is one column, its three bytes shown whole
            "u.txt:1:31: error: e\n"
            "...wxyz\xE2\x82\xAC" "01234...\n"
            "       ^\n");
  EXPECT_EQ(render_in(1, 12),
            "u.txt:1:2: error: e\n"
            "...\xC3\xA9   ...\n"
            "   ^\n");
}

TEST_F(RenderText, AOneLineMeshQuotesAWindowNotTheLine) {
  std::string mesh = "Shape \"trianglemesh\" \"point P\" [";
  for (int i = 0; i < 20000; ++i) mesh += "0 1 2 ";
  mesh += "x ]\n";
  FileId f = add("mesh.pbrt", mesh);
  const auto at = static_cast<std::uint32_t>(mesh.find('x'));
  std::string text = render_text(Diagnostic::error(range(f, at, at + 1), "expected a number"), sm);
  // 160 columns: "..." and the last 157 columns of the line, the caret under 'x'.
  EXPECT_EQ(text, "mesh.pbrt:1:120033: error: expected a number\n..." + mesh.substr(mesh.size() - 1 - 157) +
                      std::string(3 + 154, ' ') + "^\n");
}

}  // namespace
}  // namespace safegi
