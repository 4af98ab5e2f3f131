#pragma once
// The raw lexer: bytes of one file to tokens, with comments, line
// continuations and invalid bytes handled. It knows nothing of directives;
// the preprocessor drives it.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/token.hpp>

namespace safegi {

struct LexerOptions {
  // Words are classified in this context; with classify_words = false every
  // word is an identifier (the preprocessor classifies after macro expansion).
  KeywordContext keywords = KeywordContext::everything();
  bool classify_words = true;
  // Report malformed numbers ("09", "1.0x") here; the preprocessor turns this
  // off and checks the numbers that reach its output, as a C preprocessor
  // accepts any pp-number (`#define SUFFIX 1D` is fine until it is used).
  bool check_numbers = true;
  // Report bytes that are no GLSL token (`@`, non-ASCII outside comments).
  // Off in the preprocessor, which reports the ones that reach its output:
  // an unused macro body may hold anything.
  bool check_characters = true;
};

// The error for an `invalid` token's spelling, e.g. "invalid character '@' in program".
std::string invalid_character_message(std::string_view spelling);

class Lexer {
 public:
  Lexer(SourceManager& sources, FileId file, DiagnosticEngine& diagnostics, LexerOptions options = {});

  // The next token; at the end of the file, an eof token (again and again).
  Token next();

  // Skips blanks and comments and tells whether the next token starts a new
  // line (or is the end of the file), without lexing it: the preprocessor
  // ends a directive line here before deciding whether to skip what follows.
  bool next_starts_line();

  // Lexing errors are not reported while this is off (skipped #if groups);
  // an unterminated block comment is always reported.
  void set_report_errors(bool report) { report_errors_ = report; }

  // In a skipped #if group: moves past every line that is not a directive
  // without lexing its tokens (skipped text is never tokenised, only its
  // comments and line splices matter), up to a `#` that starts a line or the
  // end of the file. Large shaders skip most of their text this way.
  void skip_to_directive_line();

  // Skips to the end of the current line (the newline is left for next()),
  // returning the range of the skipped text without surrounding blanks and
  // without a trailing // comment. For #error and friends.
  SourceRange rest_of_line();

  // After `#include`: lexes `<path>` as one string_literal token whose text is
  // "<path>" (the angle brackets kept); nullopt (nothing consumed) if the
  // line continues with anything else.
  std::optional<Token> header_name();

  FileId file() const { return file_; }
  std::uint32_t offset() const { return static_cast<std::uint32_t>(pos_); }

 private:
  std::size_t skip_splices(std::size_t p) const;
  char at(std::size_t p) const { return p < text_.size() ? text_[p] : '\0'; }
  bool at_end(std::size_t p) const { return skip_splices(p) >= text_.size(); }
  char peek() const { return at(skip_splices(pos_)); }
  char peek2() const { return at(skip_splices(skip_splices(pos_) + 1)); }
  void advance() { pos_ = skip_splices(pos_) + 1; }

  bool skip_blanks_and_comments();  // true if something was skipped
  void lex_number(Token& token);
  void lex_word(Token& token);
  void lex_punctuator(Token& token);
  void lex_invalid(Token& token);
  void finish(Token& token, std::size_t begin);
  void error(const char* code, std::size_t begin, std::size_t end, std::string message);  // code: codes.def

  SourceManager& sources_;
  DiagnosticEngine& diagnostics_;
  FileId file_;
  std::string_view text_;
  LexerOptions options_;
  std::size_t pos_ = 0;
  bool at_line_start_ = true;
  bool pending_space_ = false;  // blanks skipped by next_starts_line()
  std::uint32_t line_hint_ = 0;  // line of the last token, for SourceManager::location_after
  bool report_errors_ = true;
};

// Lexes a whole file (no preprocessing); the vector ends with an eof token.
std::vector<Token> tokenize(SourceManager& sources, FileId file, DiagnosticEngine& diagnostics,
                            LexerOptions options = {});

}  // namespace safegi
