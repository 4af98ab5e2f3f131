// Scene files may hold any byte, and error messages quote them: bytes outside
// printable ASCII are written as \xHH so that a terminal shows what was read.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace safegi::render {

// `limit`: after that many characters of output the rest becomes "...".
inline std::string printable(std::string_view text, std::size_t limit = std::string::npos) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string result;
  for (unsigned char c : text) {
    if (result.size() > limit) return result + "...";
    if (c >= 0x20 && c < 0x7f)
      result += static_cast<char>(c);
    else
      result += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
  }
  return result;
}

}  // namespace safegi::render
