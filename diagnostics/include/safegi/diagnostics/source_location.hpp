#pragma once
// Positions in source text. Every stage reports through these, so they are
// small values: a file, a byte offset, and the 1-based line and byte column the
// offset falls on (columns count bytes, as clang's do).

#include <cstdint>

namespace safegi {

using FileId = std::uint32_t;
inline constexpr FileId kNoFile = 0;  // FileIds handed out by SourceManager start at 1

// Index into SourceManager's macro-expansion table; 0 means "not from a macro".
using ExpansionId = std::uint32_t;
inline constexpr ExpansionId kNoExpansion = 0;

struct SourceLocation {
  FileId file = kNoFile;
  std::uint32_t offset = 0;
  std::uint32_t line = 0;    // 1-based; 0 only for an invalid location
  std::uint32_t column = 0;  // 1-based, in bytes

  bool valid() const { return file != kNoFile; }
  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

// Half-open: `end` is the position just past the last byte.
struct SourceRange {
  SourceLocation begin;
  SourceLocation end;

  bool valid() const { return begin.valid(); }
  std::uint32_t length() const { return end.offset - begin.offset; }
  friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

}  // namespace safegi
