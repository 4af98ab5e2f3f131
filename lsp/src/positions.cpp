#include "positions.hpp"

#include <algorithm>

namespace safegi::lsp {
namespace {

// Length of the UTF-8 sequence starting at text[i] (1 for a byte that starts none).
std::size_t sequence_length(std::string_view text, std::size_t i) {
  const auto byte = static_cast<unsigned char>(text[i]);
  const std::size_t length = byte < 0x80 ? 1 : byte >= 0xC2 && byte <= 0xDF ? 2 : byte >= 0xE0 && byte <= 0xEF ? 3
                           : byte >= 0xF0 && byte <= 0xF4 ? 4 : 1;
  if (i + length > text.size()) return 1;
  for (std::size_t k = 1; k < length; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 1;
  return length;
}

std::size_t units_of(std::size_t sequence, Encoding encoding) {
  switch (encoding) {
    case Encoding::utf8: return sequence;
    case Encoding::utf16: return sequence == 4 ? 2 : 1;
    case Encoding::utf32: return 1;
  }
  return 1;
}

}  // namespace

std::string_view encoding_name(Encoding encoding) {
  switch (encoding) {
    case Encoding::utf8: return "utf-8";
    case Encoding::utf16: return "utf-16";
    case Encoding::utf32: return "utf-32";
  }
  return "utf-16";
}

std::size_t code_units(std::string_view text, Encoding encoding) {
  std::size_t units = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = sequence_length(text, i);
    units += units_of(n, encoding);
    i += n;
  }
  return units;
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    if (text[i] == '\n' || text[i] == '\r') starts_.push_back(i + 1);
  }
}

std::string_view LineIndex::line(std::uint32_t index) const {
  const std::size_t begin = starts_[index];
  std::size_t end = index + 1 < starts_.size() ? starts_[index + 1] : text_.size();
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return text_.substr(begin, end - begin);
}

Position LineIndex::position_of(std::size_t offset, Encoding encoding) const {
  offset = std::min(offset, text_.size());
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const auto index = static_cast<std::uint32_t>(after - starts_.begin() - 1);
  const std::string_view text = line(index);
  // An offset inside the line terminator is the end of the line.
  const std::size_t column = std::min(offset - starts_[index], text.size());
  std::size_t units = 0;
  for (std::size_t i = 0; i < column;) {
    const std::size_t n = sequence_length(text, i);
    if (i + n > column) break;  // inside a sequence: its start
    units += units_of(n, encoding);
    i += n;
  }
  return {index, static_cast<std::uint32_t>(units)};
}

std::size_t LineIndex::offset_of(Position position, Encoding encoding) const {
  if (position.line >= starts_.size()) return text_.size();
  const std::string_view text = line(position.line);
  std::size_t units = 0, i = 0;
  while (i < text.size()) {
    const std::size_t n = sequence_length(text, i);
    const std::size_t next = units + units_of(n, encoding);
    if (next > position.character) break;  // the position is inside this code point: its start
    units = next;
    i += n;
  }
  return starts_[position.line] + i;
}

}  // namespace safegi::lsp
