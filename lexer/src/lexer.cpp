#include <safegi/lexer/lexer.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

#include <safegi/diagnostics/codes.hpp>

namespace safegi {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_word_char(char c) { return is_word_start(c) || is_digit(c); }
bool is_newline(char c) { return c == '\n' || c == '\r'; }
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

}  // namespace

Lexer::Lexer(SourceManager& sources, FileId file, DiagnosticEngine& diagnostics, LexerOptions options)
    : sources_(sources), diagnostics_(diagnostics), file_(file), text_(sources.text(file)), options_(options) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // a UTF-8 byte order mark is not text
}

std::size_t Lexer::skip_splices(std::size_t p) const {
  while (p + 1 < text_.size() && text_[p] == '\\') {
    if (text_[p + 1] == '\n') {
      p += 2;
    } else if (text_[p + 1] == '\r') {
      p += (p + 2 < text_.size() && text_[p + 2] == '\n') ? 3 : 2;
    } else {
      break;
    }
  }
  return p;
}

void Lexer::error(const char* code, std::size_t begin, std::size_t end, std::string message) {
  if (!report_errors_) return;
  diagnostics_.report(
      Diagnostic::error(sources_.range_of(file_, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)),
                        std::move(message))
          .with_code(code));
}

bool Lexer::skip_blanks_and_comments() {
  bool skipped = false;
  for (;;) {
    pos_ = skip_splices(pos_);
    if (pos_ >= text_.size()) return skipped;
    char c = text_[pos_];
    if (is_blank(c)) {
      ++pos_;
      while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;  // indentation
    } else if (is_newline(c)) {
      pos_ += (c == '\r' && at(pos_ + 1) == '\n') ? 2 : 1;
      at_line_start_ = true;
    } else if (c == '/' && peek2() == '/') {
      for (;;) {
        // Plain characters first, a byte at a time; a backslash may splice the comment on.
        while (pos_ < text_.size() && text_[pos_] != '\\' && !is_newline(text_[pos_])) ++pos_;
        if (at_end(pos_) || is_newline(peek())) break;
        advance();
      }
    } else if (c == '/' && peek2() == '*') {
      std::size_t start = pos_;
      advance();
      advance();
      for (;;) {
        while (pos_ < text_.size() && text_[pos_] != '*' && text_[pos_] != '\\') ++pos_;  // plain characters
        if (at_end(pos_)) {
          // Reported even in skipped groups: it swallows the rest of the file.
          bool report = report_errors_;
          report_errors_ = true;
          error(code::E_UNTERMINATED_COMMENT, start, start + 2, "unterminated /* comment");
          report_errors_ = report;
          pos_ = text_.size();
          return true;
        }
        if (peek() == '*' && peek2() == '/') {
          advance();
          advance();
          break;
        }
        advance();
      }
    } else {
      return skipped;
    }
    skipped = true;
  }
}

void Lexer::skip_to_directive_line() {
  for (;;) {
    skip_blanks_and_comments();  // comments (a block comment may hide a `#`), newlines
    if (pos_ >= text_.size() || (at_line_start_ && text_[pos_] == '#')) return;
    at_line_start_ = false;
    // The rest of the logical line, up to its newline or a comment, which the
    // loop's skip_blanks_and_comments() then reads as next() would.
    for (pos_ = skip_splices(pos_); pos_ < text_.size(); pos_ = skip_splices(pos_)) {
      char c = text_[pos_];
      if (is_newline(c) || (c == '/' && (peek2() == '/' || peek2() == '*'))) break;
      ++pos_;
      // Plain characters up to one that may end the line, start a comment or splice lines.
      while (pos_ < text_.size() && text_[pos_] != '\\' && text_[pos_] != '/' && !is_newline(text_[pos_])) ++pos_;
    }
  }
}

void Lexer::finish(Token& token, std::size_t begin) {
  token.range.begin = sources_.location_after(file_, static_cast<std::uint32_t>(begin), line_hint_);
  std::string_view raw = text_.substr(begin, pos_ - begin);
  if (std::none_of(raw.begin(), raw.end(), [](char c) { return c == '\\' || is_newline(c); })) {
    // One line, no splice (nearly every token): the end is on the line the beginning is.
    token.range.end = token.range.begin;
    token.range.end.offset = static_cast<std::uint32_t>(pos_);
    token.range.end.column += static_cast<std::uint32_t>(pos_ - begin);
    token.text = raw;
    return;
  }
  token.range.end = sources_.location_after(file_, static_cast<std::uint32_t>(pos_), line_hint_);
  if (raw.find('\\') == std::string_view::npos) {
    token.text = raw;
    return;
  }
  std::string spelled;
  for (std::size_t p = skip_splices(begin); p < pos_; p = skip_splices(p + 1)) spelled.push_back(text_[p]);
  token.text = sources_.save_string(spelled);
}

bool Lexer::next_starts_line() {
  pending_space_ = skip_blanks_and_comments() || pending_space_;
  return at_line_start_ || pos_ >= text_.size();
}

Token Lexer::next() {
  Token token;
  token.leading_space = skip_blanks_and_comments() || pending_space_;
  pending_space_ = false;
  token.at_line_start = at_line_start_;
  at_line_start_ = false;
  std::size_t begin = pos_ = skip_splices(pos_);
  if (pos_ >= text_.size()) {
    token.kind = TokenKind::eof;
    token.at_line_start = true;
    finish(token, begin);
    return token;
  }
  char c = text_[pos_];
  if (is_digit(c) || (c == '.' && is_digit(peek2()))) {
    lex_number(token);
  } else if (is_word_start(c)) {
    lex_word(token);
  } else if (c == '"') {
    advance();
    while (!at_end(pos_) && peek() != '"' && !is_newline(peek())) advance();
    if (peek() == '"') {
      advance();
    } else {
      error(code::E_CHARACTER, begin, pos_, "missing terminating '\"' character");
    }
    token.kind = TokenKind::string_literal;
    finish(token, begin);
  } else {
    lex_punctuator(token);
    if (token.kind == TokenKind::invalid) lex_invalid(token);
  }
  return token;
}

void Lexer::lex_word(Token& token) {
  std::size_t begin = pos_;
  for (;;) {
    while (pos_ < text_.size() && is_word_char(text_[pos_])) ++pos_;  // no splice among them
    if (!is_word_char(peek())) break;
    advance();
  }
  finish(token, begin);
  token.kind = options_.classify_words ? classify_word(token.text, options_.keywords) : TokenKind::identifier;
}

// Scans a pp-number: digits, letters, '_' and '.', and a sign right after an
// exponent 'e' (not in hex, where 'e' is a digit); check_numeric_literal()
// then says what it means.
void Lexer::lex_number(Token& token) {
  std::size_t begin = pos_;
  bool hex = peek() == '0' && (peek2() == 'x' || peek2() == 'X');
  for (;;) {
    char c = peek();
    if (!hex && (c == 'e' || c == 'E') && (peek2() == '+' || peek2() == '-')) {
      advance();
      advance();
    } else if (is_word_char(c) || c == '.') {
      advance();
    } else {
      break;
    }
  }
  finish(token, begin);
  NumericLiteralCheck check = check_numeric_literal(token.text);
  token.kind = check.kind;
  if (check.error.empty() || !options_.check_numbers) return;
  if (token.range.length() == token.text.size()) {
    error(code::E_LITERAL, begin + check.error_begin, begin + check.error_end, std::move(check.error));
  } else {
    error(code::E_LITERAL, begin, pos_, std::move(check.error));
  }
}

void Lexer::lex_punctuator(Token& token) {
  std::size_t begin = pos_;
  char c = peek();
  char n = peek2();
  auto one = [&](TokenKind k) {
    advance();
    token.kind = k;
  };
  auto two = [&](TokenKind k) {
    advance();
    advance();
    token.kind = k;
  };
  switch (c) {
    case '(': one(TokenKind::l_paren); break;
    case ')': one(TokenKind::r_paren); break;
    case '[': one(TokenKind::l_bracket); break;
    case ']': one(TokenKind::r_bracket); break;
    case '{': one(TokenKind::l_brace); break;
    case '}': one(TokenKind::r_brace); break;
    case '.': one(TokenKind::dot); break;
    case ',': one(TokenKind::comma); break;
    case ';': one(TokenKind::semicolon); break;
    case ':': one(TokenKind::colon); break;
    case '?': one(TokenKind::question); break;
    case '~': one(TokenKind::tilde); break;
    case '+':
      if (n == '+') two(TokenKind::plus_plus);
      else if (n == '=') two(TokenKind::plus_equal);
      else one(TokenKind::plus);
      break;
    case '-':
      if (n == '-') two(TokenKind::minus_minus);
      else if (n == '=') two(TokenKind::minus_equal);
      else one(TokenKind::minus);
      break;
    case '*': n == '=' ? two(TokenKind::star_equal) : one(TokenKind::star); break;
    case '/': n == '=' ? two(TokenKind::slash_equal) : one(TokenKind::slash); break;
    case '%': n == '=' ? two(TokenKind::percent_equal) : one(TokenKind::percent); break;
    case '=': n == '=' ? two(TokenKind::equal_equal) : one(TokenKind::equal); break;
    case '!': n == '=' ? two(TokenKind::bang_equal) : one(TokenKind::bang); break;
    case '#': n == '#' ? two(TokenKind::hash_hash) : one(TokenKind::hash); break;
    case '<':
      if (n == '<') {
        advance();
        peek2() == '=' ? two(TokenKind::less_less_equal) : one(TokenKind::less_less);
      } else if (n == '=') {
        two(TokenKind::less_equal);
      } else {
        one(TokenKind::less);
      }
      break;
    case '>':
      if (n == '>') {
        advance();
        peek2() == '=' ? two(TokenKind::greater_greater_equal) : one(TokenKind::greater_greater);
      } else if (n == '=') {
        two(TokenKind::greater_equal);
      } else {
        one(TokenKind::greater);
      }
      break;
    case '&':
      if (n == '&') two(TokenKind::amp_amp);
      else if (n == '=') two(TokenKind::amp_equal);
      else one(TokenKind::amp);
      break;
    case '|':
      if (n == '|') two(TokenKind::pipe_pipe);
      else if (n == '=') two(TokenKind::pipe_equal);
      else one(TokenKind::pipe);
      break;
    case '^':
      if (n == '^') two(TokenKind::caret_caret);
      else if (n == '=') two(TokenKind::caret_equal);
      else one(TokenKind::caret);
      break;
    default: token.kind = TokenKind::invalid; return;
  }
  finish(token, begin);
}

void Lexer::lex_invalid(Token& token) {
  std::size_t begin = pos_;
  token.kind = TokenKind::invalid;
  if (static_cast<unsigned char>(text_[pos_]) >= 0x80) {
    while (pos_ < text_.size() && static_cast<unsigned char>(text_[pos_]) >= 0x80) ++pos_;  // one UTF-8 run
  } else {
    ++pos_;
  }
  finish(token, begin);
  if (options_.check_characters) error(code::E_CHARACTER, begin, pos_, invalid_character_message(token.text));
}

std::string invalid_character_message(std::string_view spelling) {
  auto byte = spelling.empty() ? 0u : static_cast<unsigned char>(spelling[0]);
  if (byte >= 0x80) return "non-ASCII character '" + std::string(spelling) + "' outside a comment";
  if (byte == '\\') return "stray '\\' in program (a line continuation must be the last character on its line)";
  if (byte < 0x20 || byte == 0x7F) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", byte);
    return std::string("invalid control character ") + hex + " in program";
  }
  return "invalid character '" + std::string(1, static_cast<char>(byte)) + "' in program";
}

SourceRange Lexer::rest_of_line() {
  std::size_t begin = std::string_view::npos;
  std::size_t last = pos_;
  for (;;) {
    pos_ = skip_splices(pos_);
    if (pos_ >= text_.size() || is_newline(text_[pos_])) break;
    char c = text_[pos_];
    if (c == '/' && peek2() == '/') break;
    if (c == '/' && peek2() == '*') {
      bool save_line_start = at_line_start_;
      skip_blanks_and_comments();  // stops at the next token or newline
      at_line_start_ = save_line_start;
      continue;
    }
    if (!is_blank(c)) {
      if (begin == std::string_view::npos) begin = pos_;
      last = pos_ + 1;
    }
    ++pos_;
  }
  while (!at_end(pos_) && !is_newline(peek())) advance();  // a trailing // comment
  if (begin == std::string_view::npos) begin = last = pos_;
  return sources_.range_of(file_, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(last));
}

std::optional<Token> Lexer::header_name() {
  std::size_t save = pos_;
  bool line_start = at_line_start_;
  bool space = skip_blanks_and_comments();
  if (at_line_start_ != line_start || peek() != '<') {
    pos_ = save;
    at_line_start_ = line_start;
    return std::nullopt;
  }
  std::size_t begin = skip_splices(pos_);
  while (!at_end(pos_) && peek() != '>' && !is_newline(peek())) advance();
  if (peek() != '>') {
    pos_ = save;
    at_line_start_ = line_start;
    return std::nullopt;
  }
  advance();
  Token token;
  token.kind = TokenKind::string_literal;
  token.leading_space = space;
  finish(token, begin);
  return token;
}

std::vector<Token> tokenize(SourceManager& sources, FileId file, DiagnosticEngine& diagnostics, LexerOptions options) {
  Lexer lexer(sources, file, diagnostics, options);
  std::vector<Token> tokens;
  for (;;) {
    tokens.push_back(lexer.next());
    if (tokens.back().kind == TokenKind::eof) return tokens;
  }
}

}  // namespace safegi
