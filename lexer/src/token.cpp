#include <safegi/lexer/token.hpp>

#include <array>
#include <charconv>
#include <string>
#include <unordered_map>

namespace safegi {
namespace {

struct KindInfo {
  std::string_view name;
  std::string_view spelling;
  std::string_view description;
  KeywordCategory category;
};

constexpr std::array<KindInfo, kTokenKindCount> kKindInfo = {{
#define SAFEGI_TOKEN(name, description) {#name, "", description, KeywordCategory::none},
#define SAFEGI_PUNCTUATOR(name, spelling) {#name, spelling, "'" spelling "'", KeywordCategory::none},
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) \
  {#name, spelling, "'" spelling "'", KeywordCategory::category},
#include <safegi/lexer/token_kinds.def>
}};

struct WordInfo {
  TokenKind kind;  // TokenKind::reserved_word for reserved-only words
  std::uint16_t desktop_since;
  std::uint16_t es_since;
  ExtensionGroup group;
  std::uint16_t es_reserved_from;
  std::uint16_t desktop_reserved_from = 0;
  std::uint16_t desktop_reserved_until = 0;  // reserved words only: an identifier from this version on
  std::uint16_t es_reserved_until = 0;
};

std::unordered_map<std::string_view, WordInfo> make_word_table() {
  std::unordered_map<std::string_view, WordInfo> table = {
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) \
  {spelling, {TokenKind::name, desktop_since, es_since, ExtensionGroup::group, es_reserved_from}},
#define SAFEGI_RESERVED_WORD(spelling, desktop_since, es_since) \
  {spelling, {TokenKind::reserved_word, desktop_since, es_since, ExtensionGroup::none, 0}},
#include <safegi/lexer/token_kinds.def>
  };
#define SAFEGI_DESKTOP_RESERVED_BEFORE_KEYWORD(spelling, desktop_from) \
  table.at(spelling).desktop_reserved_from = desktop_from;
#define SAFEGI_RESERVED_UNTIL(spelling, desktop_until, es_until) \
  table.at(spelling).desktop_reserved_until = desktop_until;      \
  table.at(spelling).es_reserved_until = es_until;
#include <safegi/lexer/token_kinds.def>
  return table;
}

const std::unordered_map<std::string_view, WordInfo>& word_table() {
  static const std::unordered_map<std::string_view, WordInfo> table = make_word_table();
  return table;
}

const KindInfo& info(TokenKind kind) { return kKindInfo[static_cast<std::size_t>(kind)]; }

struct Suffix {
  std::string_view spelling;
  TokenKind kind;
};
constexpr Suffix kIntegerSuffixes[] = {
    {"", TokenKind::int_literal},       {"u", TokenKind::uint_literal},     {"U", TokenKind::uint_literal},
    {"l", TokenKind::int64_literal},    {"L", TokenKind::int64_literal},    {"ul", TokenKind::uint64_literal},
    {"UL", TokenKind::uint64_literal},  {"uL", TokenKind::uint64_literal},  {"Ul", TokenKind::uint64_literal},
    {"s", TokenKind::int16_literal},    {"S", TokenKind::int16_literal},    {"us", TokenKind::uint16_literal},
    {"US", TokenKind::uint16_literal},
};
constexpr Suffix kFloatSuffixes[] = {
    {"", TokenKind::float_literal},     {"f", TokenKind::float_literal},     {"F", TokenKind::float_literal},
    {"lf", TokenKind::double_literal},  {"LF", TokenKind::double_literal},  {"lF", TokenKind::double_literal},
    {"Lf", TokenKind::double_literal},  {"hf", TokenKind::float16_literal}, {"HF", TokenKind::float16_literal},
    {"hF", TokenKind::float16_literal}, {"Hf", TokenKind::float16_literal},
};

template <std::size_t N>
const Suffix* find_suffix(const Suffix (&suffixes)[N], std::string_view spelling) {
  for (const Suffix& s : suffixes) {
    if (s.spelling == spelling) return &s;
  }
  return nullptr;
}

std::uint64_t max_value(TokenKind kind) {
  switch (kind) {
    case TokenKind::int16_literal:
    case TokenKind::uint16_literal: return 0xFFFF;
    case TokenKind::int64_literal:
    case TokenKind::uint64_literal: return UINT64_MAX;
    default: return 0xFFFFFFFF;
  }
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex_digit(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

}  // namespace

NumericLiteralCheck check_numeric_literal(std::string_view text) {
  NumericLiteralCheck result;
  auto size = static_cast<std::uint32_t>(text.size());
  auto fail = [&](std::uint32_t begin, std::uint32_t end, std::string message) {
    result.error = std::move(message);
    result.error_begin = begin;
    result.error_end = end;
    return result;
  };
  std::size_t i = 0;
  bool hex = text.size() >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  bool is_float = false;
  if (hex) {
    i = 2;
    while (i < text.size() && is_hex_digit(text[i])) ++i;
  } else {
    while (i < text.size() && is_digit(text[i])) ++i;
    if (i < text.size() && text[i] == '.') {
      is_float = true;
      ++i;
      while (i < text.size() && is_digit(text[i])) ++i;
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      std::size_t e = i + 1;
      bool sign = e < text.size() && (text[e] == '+' || text[e] == '-');
      if (sign) ++e;
      if (e < text.size() && is_digit(text[e])) {
        is_float = true;
        i = e;
        while (i < text.size() && is_digit(text[i])) ++i;
      } else if (sign) {
        result.kind = TokenKind::float_literal;
        return fail(0, size, "exponent has no digits");
      }
    }
  }
  std::string_view digits = text.substr(0, i);
  std::string_view suffix = text.substr(i);
  auto suffix_begin = static_cast<std::uint32_t>(i);
  if (is_float) {
    const Suffix* s = find_suffix(kFloatSuffixes, suffix);
    result.kind = s ? s->kind : TokenKind::float_literal;
    if (s) return result;
    if (suffix[0] == 'e' || suffix[0] == 'E') return fail(suffix_begin, size, "exponent has no digits");
    return fail(suffix_begin, size, "invalid suffix '" + std::string(suffix) + "' on floating-point literal");
  }
  const Suffix* s = find_suffix(kIntegerSuffixes, suffix);
  if (!s && !hex && (suffix == "f" || suffix == "F" || suffix == "lf" || suffix == "LF")) {
    result.kind = TokenKind::float_literal;
    return fail(0, size, "a floating-point literal needs a '.' or an exponent (write '" + std::string(digits) +
                             ".0" + std::string(suffix) + "')");
  }
  result.kind = s ? s->kind : TokenKind::int_literal;
  if (!s) {
    if (!hex && (suffix[0] == 'e' || suffix[0] == 'E')) return fail(suffix_begin, size, "exponent has no digits");
    return fail(suffix_begin, size, "invalid suffix '" + std::string(suffix) + "' on integer literal");
  }
  if (hex && digits.size() == 2) return fail(0, size, "hexadecimal literal has no digits");
  if (!hex && digits.size() > 1 && digits[0] == '0') {
    std::size_t bad = digits.find_first_of("89");
    if (bad != std::string_view::npos) {
      return fail(0, size, std::string("invalid digit '") + digits[bad] + "' in octal literal");
    }
  }
  auto value = integer_literal_value(digits);
  if (!value || *value > max_value(result.kind)) {
    unsigned bits = max_value(result.kind) == 0xFFFF ? 16 : max_value(result.kind) == 0xFFFFFFFF ? 32 : 64;
    return fail(0, size, "integer literal '" + std::string(text) + "' does not fit in " + std::to_string(bits) + " bits");
  }
  return result;
}

KeywordContext KeywordContext::everything() {
  KeywordContext context;
  context.version = 460;
  context.extension_groups = ~0u & ~(1u << static_cast<unsigned>(ExtensionGroup::vulkan));
  return context;
}

TokenKind classify_word(std::string_view word, const KeywordContext& context) {
  const auto& table = word_table();
  auto it = table.find(word);
  if (it == table.end()) return TokenKind::identifier;
  const WordInfo& w = it->second;
  int since = context.es ? w.es_since : w.desktop_since;
  bool available = (since != 0 && context.version >= since) ||
                   (w.group != ExtensionGroup::none && context.enabled(w.group));
  const int until = context.es ? w.es_reserved_until : w.desktop_reserved_until;
  if (available && w.kind == TokenKind::reserved_word && until != 0 && context.version >= until)
    return TokenKind::identifier;
  if (available) return w.kind;
  if (context.es && w.es_reserved_from != 0 && context.version >= w.es_reserved_from) {
    return TokenKind::reserved_word;
  }
  if (!context.es && w.desktop_reserved_from != 0 && context.version >= w.desktop_reserved_from) {
    return TokenKind::reserved_word;
  }
  return TokenKind::identifier;
}

std::string_view token_kind_name(TokenKind kind) { return info(kind).name; }
std::string_view token_kind_spelling(TokenKind kind) { return info(kind).spelling; }
std::string_view token_kind_description(TokenKind kind) { return info(kind).description; }

bool is_keyword(TokenKind kind) { return info(kind).category != KeywordCategory::none; }
bool is_punctuator(TokenKind kind) { return kind >= TokenKind::l_paren && kind <= TokenKind::hash_hash; }
bool is_numeric_literal(TokenKind kind) {
  return kind >= TokenKind::int_literal && kind <= TokenKind::float16_literal;
}
bool is_literal(TokenKind kind) {
  return is_numeric_literal(kind) || kind == TokenKind::kw_true || kind == TokenKind::kw_false;
}
KeywordCategory keyword_category(TokenKind kind) { return info(kind).category; }

std::optional<std::pair<Token, Token>> split_leading_greater(const Token& token) {
  TokenKind rest;
  switch (token.kind) {
    case TokenKind::greater_greater: rest = TokenKind::greater; break;
    case TokenKind::greater_equal: rest = TokenKind::equal; break;
    case TokenKind::greater_greater_equal: rest = TokenKind::greater_equal; break;
    default: return std::nullopt;
  }
  Token first = token;
  Token second = token;
  first.kind = TokenKind::greater;
  first.text = token.text.substr(0, 1);
  second.kind = rest;
  second.text = token.text.substr(1);
  second.leading_space = false;
  second.at_line_start = false;
  // Only a spelling without line continuations maps byte for byte onto its range.
  if (token.range.length() == token.text.size()) {
    first.range.end = token.range.begin;
    first.range.end.offset += 1;
    first.range.end.column += 1;
    second.range.begin = first.range.end;
  }
  return std::make_pair(first, second);
}

std::optional<std::uint64_t> integer_literal_value(std::string_view text) {
  int base = 10;
  std::size_t i = 0;
  if (text.size() >= 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    base = 16;
    i = 2;
  } else if (text.size() >= 2 && text[0] == '0') {
    base = 8;
  }
  std::uint64_t value = 0;
  std::size_t digits = 0;
  for (; i < text.size(); ++i) {
    char c = text[i];
    int d;
    if (c >= '0' && c <= '9') d = c - '0';
    else if (base == 16 && c >= 'a' && c <= 'f') d = c - 'a' + 10;
    else if (base == 16 && c >= 'A' && c <= 'F') d = c - 'A' + 10;
    else break;
    if (d >= base) return std::nullopt;
    if (value > (UINT64_MAX - static_cast<unsigned>(d)) / static_cast<unsigned>(base)) return std::nullopt;
    value = value * static_cast<unsigned>(base) + static_cast<unsigned>(d);
    ++digits;
  }
  if (digits == 0 && base != 8) return std::nullopt;
  return value;
}

double float_literal_value(std::string_view text) {
  std::size_t end = text.find_first_not_of("0123456789.eE+-");
  std::string_view digits = text.substr(0, end);
  double value = 0.0;
  std::from_chars(digits.data(), digits.data() + digits.size(), value);  // locale-independent
  return value;
}

}  // namespace safegi
