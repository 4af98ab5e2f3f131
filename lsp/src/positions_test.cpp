// LSP positions against byte offsets, in the three encodings, on lines with
// non-ASCII text (Φ is 2 bytes in UTF-8, → 3, 😀 4 and a surrogate pair in UTF-16).
#include "positions.hpp"

#include <gtest/gtest.h>

namespace safegi::lsp {
namespace {

const std::string kText = "ab\n// Φ→😀 x\r\ny\rz";
//                          0   3  6 8 11 16 18   20 21

TEST(Positions, Utf16CountsSurrogatePairsAsTwo) {
  const LineIndex lines(kText);
  ASSERT_EQ(lines.line_count(), 4u);
  const std::size_t x = kText.find('x');
  EXPECT_EQ(lines.position_of(x, Encoding::utf16), (Position{1, 8}));   // "// " 3 + Φ 1 + → 1 + 😀 2 + " " 1
  EXPECT_EQ(lines.position_of(x, Encoding::utf8), (Position{1, 13}));   // bytes
  EXPECT_EQ(lines.position_of(x, Encoding::utf32), (Position{1, 7}));   // code points
  for (Encoding e : {Encoding::utf8, Encoding::utf16, Encoding::utf32})
    EXPECT_EQ(lines.offset_of(lines.position_of(x, e), e), x) << encoding_name(e);
}

TEST(Positions, LinesEndAtLfCrLfAndCr) {
  const LineIndex lines(kText);
  EXPECT_EQ(lines.position_of(kText.find('y'), Encoding::utf16), (Position{2, 0}));
  EXPECT_EQ(lines.position_of(kText.find('z'), Encoding::utf16), (Position{3, 0}));
  // Inside a line terminator: the end of its line.
  EXPECT_EQ(lines.position_of(kText.find('\n', 4) , Encoding::utf16), (Position{1, 9}));
  EXPECT_EQ(lines.position_of(kText.size(), Encoding::utf16), (Position{3, 1}));
}

TEST(Positions, OutOfRangeClampsAndInsideACodePointFallsBackToItsStart) {
  const LineIndex lines(kText);
  EXPECT_EQ(lines.offset_of({0, 99}, Encoding::utf16), 2u);            // past the end of "ab": its end
  EXPECT_EQ(lines.offset_of({99, 0}, Encoding::utf16), kText.size());  // past the last line: the end
  const std::size_t emoji = kText.find("😀");
  EXPECT_EQ(lines.offset_of({1, 6}, Encoding::utf16), emoji);          // between the surrogates
  EXPECT_EQ(lines.offset_of({1, 7}, Encoding::utf8), kText.find("→"));  // byte 7 of the line is inside →
  EXPECT_EQ(lines.position_of(emoji + 2, Encoding::utf16), (Position{1, 5}));  // a byte inside 😀
  EXPECT_EQ(lines.position_of(999, Encoding::utf8), (Position{3, 1}));
}

TEST(Positions, BytesThatAreNotUtf8CountOnce) {
  const std::string text = "a\xff\xc3z";
  const LineIndex lines(text);
  EXPECT_EQ(lines.position_of(3, Encoding::utf16), (Position{0, 3}));
  EXPECT_EQ(code_units(text, Encoding::utf16), 4u);
  EXPECT_EQ(code_units("Φ→😀", Encoding::utf16), 4u);
  EXPECT_EQ(code_units("Φ→😀", Encoding::utf8), 9u);
}

TEST(Positions, EmptyText) {
  const LineIndex lines("");
  EXPECT_EQ(lines.line_count(), 1u);
  EXPECT_EQ(lines.position_of(0, Encoding::utf16), (Position{0, 0}));
  EXPECT_EQ(lines.offset_of({3, 4}, Encoding::utf16), 0u);
}

}  // namespace
}  // namespace safegi::lsp
