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
};

const std::unordered_map<std::string_view, WordInfo>& word_table() {
  static const std::unordered_map<std::string_view, WordInfo> table = {
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) \
  {spelling, {TokenKind::name, desktop_since, es_since, ExtensionGroup::group, es_reserved_from}},
#define SAFEGI_RESERVED_WORD(spelling, desktop_since, es_since) \
  {spelling, {TokenKind::reserved_word, desktop_since, es_since, ExtensionGroup::none, 0}},
#include <safegi/lexer/token_kinds.def>
  };
  return table;
}

const KindInfo& info(TokenKind kind) { return kKindInfo[static_cast<std::size_t>(kind)]; }

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

KeywordContext KeywordContext::everything() {
  KeywordContext context;
  context.version = 460;
  context.extension_groups = ~0u;
  return context;
}

std::uint32_t extension_groups_enabled_by(std::string_view ext) {
  auto bit = [](ExtensionGroup g) { return 1u << static_cast<unsigned>(g); };
  if (ext == "GL_ARB_explicit_attrib_location" || ext == "GL_ARB_shading_language_420pack" ||
      ext == "GL_ARB_explicit_uniform_location" || ext == "GL_ARB_separate_shader_objects" ||
      ext == "GL_ARB_uniform_buffer_object")
    return bit(ExtensionGroup::layout);
  if (ext == "GL_ARB_tessellation_shader" || ext == "GL_EXT_tessellation_shader" ||
      ext == "GL_OES_tessellation_shader")
    return bit(ExtensionGroup::tessellation);
  if (ext == "GL_ARB_gpu_shader5" || ext == "GL_EXT_gpu_shader5" || ext == "GL_OES_gpu_shader5" ||
      ext == "GL_OES_shader_multisample_interpolation")
    return bit(ExtensionGroup::gpu_shader5);
  if (ext == "GL_NV_gpu_shader5") return bit(ExtensionGroup::gpu_shader5) | bit(ExtensionGroup::arithmetic_types);
  if (ext == "GL_ARB_shader_image_load_store" || ext == "GL_EXT_shader_image_load_store")
    return bit(ExtensionGroup::image_load_store);
  if (ext == "GL_ARB_shader_storage_buffer_object") return bit(ExtensionGroup::storage_buffer);
  if (ext == "GL_ARB_gpu_shader_fp64" || ext == "GL_ARB_vertex_attrib_64bit") return bit(ExtensionGroup::fp64);
  if (ext == "GL_ARB_shader_atomic_counters") return bit(ExtensionGroup::atomic_counters);
  if (ext == "GL_EXT_texture_array") return bit(ExtensionGroup::texture_array);
  if (ext == "GL_ARB_texture_rectangle") return bit(ExtensionGroup::texture_rectangle);
  if (ext == "GL_EXT_texture_buffer" || ext == "GL_OES_texture_buffer" || ext == "GL_ARB_texture_buffer_object" ||
      ext == "GL_EXT_gpu_shader4")
    return bit(ExtensionGroup::texture_buffer);
  if (ext == "GL_ARB_texture_multisample" || ext == "GL_OES_texture_storage_multisample_2d_array")
    return bit(ExtensionGroup::multisample);
  if (ext == "GL_ARB_texture_cube_map_array" || ext == "GL_EXT_texture_cube_map_array" ||
      ext == "GL_OES_texture_cube_map_array")
    return bit(ExtensionGroup::cube_map_array);
  if (ext == "GL_OES_EGL_image_external" || ext == "GL_OES_EGL_image_external_essl3")
    return bit(ExtensionGroup::external_image);
  if (ext == "GL_KHR_vulkan_glsl") return bit(ExtensionGroup::vulkan);
  if (starts_with(ext, "GL_EXT_shader_explicit_arithmetic_types") || ext == "GL_ARB_gpu_shader_int64" ||
      ext == "GL_AMD_gpu_shader_half_float" || ext == "GL_AMD_gpu_shader_int16" ||
      ext == "GL_EXT_shader_16bit_storage" || ext == "GL_EXT_shader_8bit_storage")
    return bit(ExtensionGroup::arithmetic_types);
  return 0;
}

TokenKind classify_word(std::string_view word, const KeywordContext& context) {
  const auto& table = word_table();
  auto it = table.find(word);
  if (it == table.end()) return TokenKind::identifier;
  const WordInfo& w = it->second;
  int since = context.es ? w.es_since : w.desktop_since;
  bool available = (since != 0 && context.version >= since) ||
                   (w.group != ExtensionGroup::none && context.enabled(w.group));
  if (available) return w.kind;
  if (context.es && w.es_reserved_from != 0 && context.version >= w.es_reserved_from) {
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
