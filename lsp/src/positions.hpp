#pragma once
// LSP positions are (line, character) with the character counted in code
// units of the negotiated encoding: UTF-16 by default (what the protocol
// mandates), UTF-8 when the client offers it (initialize's
// general.positionEncodings), UTF-32 too. The compiler counts bytes; a
// LineIndex converts between the two for one text.
//
// Lines end at \n, \r\n or \r, as the protocol says. A character past the end
// of its line means the end of the line; a line past the end of the text means
// the end of the text. A position inside a UTF-16 surrogate pair or a UTF-8
// sequence falls back to the start of its code point. Bytes that are not
// UTF-8 count as one code unit each (a client sees them as U+FFFD).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace safegi::lsp {

enum class Encoding { utf8, utf16, utf32 };

std::string_view encoding_name(Encoding encoding);  // "utf-8", "utf-16", "utf-32"

struct Position {
  std::uint32_t line = 0;
  std::uint32_t character = 0;
  friend bool operator==(const Position&, const Position&) = default;
};

class LineIndex {
 public:
  explicit LineIndex(std::string_view text);

  Position position_of(std::size_t offset, Encoding encoding) const;  // offset clamped to the text
  std::size_t offset_of(Position position, Encoding encoding) const;
  std::size_t line_count() const { return starts_.size(); }

 private:
  std::string_view line(std::uint32_t index) const;  // without its terminator

  std::string_view text_;
  std::vector<std::size_t> starts_;  // byte offset of each line's first byte
};

// Code units of `encoding` in `text`, which must end on a code point boundary.
std::size_t code_units(std::string_view text, Encoding encoding);

}  // namespace safegi::lsp
