#include <safegi/diagnostics/printable.hpp>

namespace safegi {
namespace {

unsigned char byte_at(std::string_view text, std::size_t at) { return static_cast<unsigned char>(text[at]); }

// The length of the well-formed UTF-8 sequence at text[at] (RFC 3629, Table 3-7
// of the Unicode standard: no overlong forms, no surrogates, nothing past
// U+10FFFF), or 0 when there is none.
std::size_t utf8_sequence_length(std::string_view text, std::size_t at) {
  const unsigned char lead = byte_at(text, at);
  std::size_t length = 0;
  unsigned char second_low = 0x80, second_high = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) second_low = 0xA0;
    if (lead == 0xED) second_high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) second_low = 0x90;
    if (lead == 0xF4) second_high = 0x8F;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  const unsigned char second = byte_at(text, at + 1);
  if (second < second_low || second > second_high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if ((byte_at(text, at + i) & 0xC0) != 0x80) return 0;
  return length;
}

// C1 controls (U+0080..U+009F: 0x9B is CSI to many terminals) and the
// bidirectional embeddings, overrides and isolates (U+202A..U+202E,
// U+2066..U+2069), which reorder what a reader sees ("Trojan Source").
bool is_unprintable_sequence(std::string_view sequence) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(sequence[i]); };
  if (sequence.size() == 2) return b(0) == 0xC2 && b(1) <= 0x9F;
  if (sequence.size() == 3 && b(0) == 0xE2) {
    return (b(1) == 0x80 && b(2) >= 0xAA && b(2) <= 0xAE) || (b(1) == 0x81 && b(2) >= 0xA6 && b(2) <= 0xA9);
  }
  return false;
}

}  // namespace

TextUnit text_unit_at(std::string_view text, std::size_t at) {
  const unsigned char c = byte_at(text, at);
  if (c < 0x80) return {1, c >= 0x20 && c != 0x7F};
  const std::size_t length = utf8_sequence_length(text, at);
  if (length == 0) return {1, false, false};
  return {length, !is_unprintable_sequence(text.substr(at, length))};
}

void append_escaped(std::string& out, std::string_view unit) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  for (unsigned char c : unit) {
    out += "\\x";
    out += kHex[c >> 4];
    out += kHex[c & 15];
  }
}

std::string escape_unprintable(std::string_view text, bool keep_line_breaks) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const TextUnit unit = text_unit_at(text, at);
    const std::string_view bytes = text.substr(at, unit.bytes);
    if (unit.printable || (keep_line_breaks && bytes == "\n")) out += bytes;
    else append_escaped(out, bytes);
    at += unit.bytes;
  }
  return out;
}

std::string escape_invalid_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const TextUnit unit = text_unit_at(text, at);
    const std::string_view bytes = text.substr(at, unit.bytes);
    if (unit.utf8) out += bytes;
    else append_escaped(out, bytes);
    at += unit.bytes;
  }
  return out;
}

std::string error_report(std::string_view what) {
  if (!what.empty() && what.back() == '\n') return escape_unprintable(what, /*keep_line_breaks=*/true);
  return "error: " + escape_unprintable(what) + "\n";
}

std::string out_of_memory_text(std::string_view doing) {
  return "out of memory while " + std::string(doing) + ": an allocation failed (std::bad_alloc)";
}

}  // namespace safegi
