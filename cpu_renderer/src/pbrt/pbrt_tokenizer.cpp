#include "pbrt/pbrt_tokenizer.hpp"

#include "util/printable.hpp"

namespace safegi::render::pbrt {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool ends_word(char c) { return is_space(c) || c == '"' || c == '[' || c == ']'; }

// Quoted text may hold any byte: keep messages printable and short.
std::string printable(std::string_view text) { return render::printable(text, 60); }

}  // namespace

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::word: return "'" + printable(token.text) + "'";
    case TokenKind::string: return "the string \"" + printable(token.text) + "\"";
    case TokenKind::open_bracket: return "'['";
    case TokenKind::close_bracket: return "']'";
    case TokenKind::end: return "the end of the file";
  }
  return "?";
}

Tokenizer::Tokenizer(const SourceManager& sources, FileId file)
    : sources_(sources), file_(file), text_(sources.text(file)) {}

SourceRange Tokenizer::range_from(std::uint32_t begin) const { return sources_.range_of(file_, begin, position_); }

Token Tokenizer::next() {
  const std::uint32_t size = static_cast<std::uint32_t>(text_.size());
  while (position_ < size) {
    char c = text_[position_];
    if (is_space(c)) {
      ++position_;
    } else if (c == '#') {
      while (position_ < size && text_[position_] != '\n' && text_[position_] != '\r') ++position_;
    } else {
      break;
    }
  }
  Token token;
  const std::uint32_t begin = position_;
  if (position_ >= size) {
    token.range = range_from(begin);
    return token;
  }
  char c = text_[position_++];
  if (c == '[' || c == ']') {
    token.kind = c == '[' ? TokenKind::open_bracket : TokenKind::close_bracket;
    token.text = std::string(1, c);
  } else if (c == '"') {
    token.kind = TokenKind::string;
    while (true) {
      if (position_ >= size || text_[position_] == '\n' || text_[position_] == '\r') {
        SourceRange opening = sources_.range_of(file_, begin, begin + 1);
        fail(opening, "unterminated string: expected '\"' before the end of the " +
                          std::string(position_ >= size ? "file" : "line"),
             "pbrt-v3 strings end on the line they start on");
      }
      char s = text_[position_++];
      if (s == '"') break;
      if (s != '\\') {
        token.text += s;
        continue;
      }
      if (position_ >= size) fail(range_from(begin), "unterminated string: the file ends after '\\'");
      char escaped = text_[position_++];
      switch (escaped) {
        case 'b': token.text += '\b'; break;
        case 'f': token.text += '\f'; break;
        case 'n': token.text += '\n'; break;
        case 'r': token.text += '\r'; break;
        case 't': token.text += '\t'; break;
        case '\\': token.text += '\\'; break;
        case '\'': token.text += '\''; break;
        case '"': token.text += '"'; break;
        default:
          fail(sources_.range_of(file_, position_ - 2, position_),
               "unknown escape '\\" + printable(std::string_view(&escaped, 1)) + "' in a string",
               "pbrt-v3 knows \\b \\f \\n \\r \\t \\\\ \\' \\\"");
      }
    }
  } else {
    token.kind = TokenKind::word;
    while (position_ < size && !ends_word(text_[position_])) ++position_;
    token.text = std::string(text_.substr(begin, position_ - begin));
  }
  token.range = range_from(begin);
  return token;
}

}  // namespace safegi::render::pbrt
