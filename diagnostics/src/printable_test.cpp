#include <safegi/diagnostics/printable.hpp>

#include <gtest/gtest.h>

namespace safegi {
namespace {

using namespace std::string_literals;

TEST(Printable, ControlBytesAreEscaped) {
  EXPECT_EQ(escape_unprintable("a\x1b[31mb\x7f\x01"), "a\\x1B[31mb\\x7F\\x01");
  EXPECT_EQ(escape_unprintable("nul\0here"s), "nul\\x00here");
  EXPECT_EQ(escape_unprintable("tab\tline\n"), "tab\\x09line\\x0A");
  EXPECT_EQ(escape_unprintable("tab\tline\n", /*keep_line_breaks=*/true), "tab\\x09line\n");
}

TEST(Printable, WellFormedUtf8StaysAsItIs) {
  EXPECT_EQ(escape_unprintable("\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"), "\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
}

TEST(Printable, MalformedUtf8C1ControlsAndBidiOverridesAreEscaped) {
  EXPECT_EQ(escape_unprintable("\xFF\xC3"), "\\xFF\\xC3");             // not UTF-8; a sequence cut short
  EXPECT_EQ(escape_unprintable("\xC0\xAF"), "\\xC0\\xAF");             // overlong '/'
  EXPECT_EQ(escape_unprintable("\xED\xA0\x80"), "\\xED\\xA0\\x80");    // a surrogate
  EXPECT_EQ(escape_unprintable("\xC2\x9B" "2J"), "\\xC2\\x9B2J");      // U+009B, CSI
  EXPECT_EQ(escape_unprintable("a\xE2\x80\xAE" "b"), "a\\xE2\\x80\\xAEb");  // U+202E, right-to-left override
  EXPECT_EQ(text_unit_at("\xE2\x82\xAC", 0).bytes, 3u);
  EXPECT_FALSE(text_unit_at("\x9B", 0).printable);
}

// The other policy, over the same validator: only what is not UTF-8 is escaped (controls,
// C1 and bidi overrides stay, for escape_unprintable when the text reaches a terminal).
TEST(Printable, EscapeInvalidUtf8KeepsEveryWellFormedSequence) {
  EXPECT_EQ(escape_invalid_utf8("\xFF\xC3"), "\\xFF\\xC3");
  EXPECT_EQ(escape_invalid_utf8("\xC0\xAF"), "\\xC0\\xAF");
  EXPECT_EQ(escape_invalid_utf8("\xED\xA0\x80"), "\\xED\\xA0\\x80");
  EXPECT_EQ(escape_invalid_utf8("tab\tline\n\x1b \xC2\x9B a\xE2\x80\xAE \xC3\xA9"), "tab\tline\n\x1b \xC2\x9B a\xE2\x80\xAE \xC3\xA9");
  EXPECT_FALSE(text_unit_at("\x9B", 0).utf8);  // a lone continuation byte
  EXPECT_TRUE(text_unit_at("\x01", 0).utf8);
}

TEST(Printable, ErrorReportKeepsAWholeDiagnosticAndPrefixesAnythingElse) {
  EXPECT_EQ(error_report("s.pbrt:1:1: error: bad\nbad\n^\n"), "s.pbrt:1:1: error: bad\nbad\n^\n");
  EXPECT_EQ(error_report("cannot open 'a\x1b]0;x\x07'"), "error: cannot open 'a\\x1B]0;x\\x07'\n");
  EXPECT_EQ(error_report("s.pbrt:1:1: error: \x1b[2J\n"), "s.pbrt:1:1: error: \\x1B[2J\n");
}

}  // namespace
}  // namespace safegi
