// pbrt-v3 scene files, stage 1: bytes → tokens. The token classes are
// pbrt-v3's own (core/parser.cpp): quoted strings (with \n, \t, \\, \" ...
// escapes, ending on the same line), '[' and ']', comments from '#' to the end
// of the line (skipped here), and bare words — directive names and numbers —
// running until whitespace, a quote or a bracket.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>

namespace safegi::render::pbrt {

// Every error of the pbrt reader and importer: one diagnostic, rendered by
// the caller against the SourceManager that owns the files.
class PbrtError : public std::runtime_error {
 public:
  explicit PbrtError(Diagnostic diagnostic)
      : std::runtime_error(diagnostic.message), diagnostic_(std::move(diagnostic)) {}
  const Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  Diagnostic diagnostic_;
};

[[noreturn]] inline void fail(SourceRange at, std::string message, std::string hint = {}) {
  Diagnostic diagnostic = Diagnostic::error(at, std::move(message));
  if (!hint.empty()) diagnostic.hint = std::move(hint);
  throw PbrtError(std::move(diagnostic));
}

enum class TokenKind { word, string, open_bracket, close_bracket, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;  // a string's contents with escapes decoded; a word as written
  SourceRange range;  // what was written, quotes included
};

// What a token is, for "expected ..., found ..." messages: `'Shape'`,
// `the string "matte"`, `'['`, `the end of the file`.
std::string describe(const Token& token);

class Tokenizer {
 public:
  Tokenizer(const SourceManager& sources, FileId file);

  Token next();
  FileId file() const { return file_; }

 private:
  SourceRange range_from(std::uint32_t begin) const;

  const SourceManager& sources_;
  FileId file_;
  std::string_view text_;
  std::uint32_t position_ = 0;
};

}  // namespace safegi::render::pbrt
