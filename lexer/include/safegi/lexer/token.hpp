#pragma once
// Tokens of GLSL 4.60 / ESSL 3.20. The kinds are data (token_kinds.def);
// which words are keywords depends on the #version, the profile and the
// enabled extensions, so the words are classified through a KeywordContext.
//
// SafeGI's annotation words (dimension, unit, space, point, vector, direction,
// normal, spectrum, map, ...) are NOT keywords: plain GLSL may use them as
// names, and the parser gives them meaning by context.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <safegi/diagnostics/source_location.hpp>

namespace safegi {

enum class TokenKind : std::uint16_t {
#define SAFEGI_TOKEN(name, description) name,
#define SAFEGI_PUNCTUATOR(name, spelling) name,
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) name,
#include <safegi/lexer/token_kinds.def>
};

inline constexpr std::size_t kTokenKindCount = [] {
  std::size_t n = 0;
#define SAFEGI_TOKEN(name, description) ++n;
#define SAFEGI_PUNCTUATOR(name, spelling) ++n;
#define SAFEGI_KEYWORD(name, spelling, category, desktop_since, es_since, group, es_reserved_from) ++n;
#include <safegi/lexer/token_kinds.def>
  return n;
}();

enum class KeywordCategory : std::uint8_t { none, type, qualifier, statement, literal, declaration };

// Extensions that turn words into keywords regardless of #version.
enum class ExtensionGroup : std::uint8_t {
  none,
  layout,             // GL_ARB_explicit_attrib_location, GL_ARB_shading_language_420pack
  tessellation,       // GL_ARB_tessellation_shader, GL_EXT/OES_tessellation_shader
  gpu_shader5,        // GL_ARB_gpu_shader5, GL_EXT/OES_gpu_shader5, GL_OES_shader_multisample_interpolation
  image_load_store,   // GL_ARB_shader_image_load_store
  storage_buffer,     // GL_ARB_shader_storage_buffer_object
  fp64,               // GL_ARB_gpu_shader_fp64, GL_ARB_vertex_attrib_64bit
  atomic_counters,    // GL_ARB_shader_atomic_counters
  texture_array,      // GL_EXT_texture_array
  texture_rectangle,  // GL_ARB_texture_rectangle
  texture_buffer,     // GL_EXT/OES_texture_buffer, GL_ARB_texture_buffer_object
  multisample,        // GL_ARB_texture_multisample, GL_OES_texture_storage_multisample_2d_array
  cube_map_array,     // GL_ARB/EXT/OES_texture_cube_map_array
  external_image,     // GL_OES_EGL_image_external(_essl3)
  vulkan,             // Vulkan GLSL (GL_KHR_vulkan_glsl): texture*, sampler, subpassInput*
  arithmetic_types,   // GL_EXT_shader_explicit_arithmetic_types*, GL_ARB_gpu_shader_int64, ...
  subroutine,         // GL_ARB_shader_subroutine
  memory_qualifiers,  // coherent, volatile, restrict, readonly, writeonly: image load/store, storage buffers
  interpolation,      // flat, smooth, noperspective, centroid: GL_EXT_gpu_shader4, GL_NV_shader_noperspective_interpolation
  unsigned_integers,  // uint, uvecN and `unsigned int`: GL_EXT_gpu_shader4
  ray_tracing,        // rayPayloadEXT, hitAttributeEXT, callableDataEXT, shaderRecordEXT (and NV): GL_EXT/NV_ray_tracing
  mesh_shading,       // taskPayloadSharedEXT, perprimitiveEXT (and NV): GL_EXT/NV_mesh_shader
  nonuniform,         // nonuniformEXT: GL_EXT_nonuniform_qualifier
  barycentric,        // pervertexEXT / pervertexNV: GL_EXT/NV_fragment_shader_barycentric
  image_int64,        // i64image*, u64image*: GL_EXT_shader_image_int64
  half_float_fetch,   // f16sampler*, f16image*, f16texture*, f16subpassInput*: GL_AMD_gpu_shader_half_float_fetch
};

// Bit mask of ExtensionGroup values that `extension` (a #extension name)
// enables; the table is in extensions.hpp (known_extensions()).
std::uint32_t extension_groups_enabled_by(std::string_view extension);

struct KeywordContext {
  int version = 460;
  bool es = false;
  std::uint32_t extension_groups = 0;  // bit (1 << ExtensionGroup)

  void enable(ExtensionGroup group) { extension_groups |= 1u << static_cast<unsigned>(group); }
  bool enabled(ExtensionGroup group) const {
    return (extension_groups >> static_cast<unsigned>(group)) & 1u;
  }
  // GLSL 4.60 with every extension group but Vulkan GLSL's (whose `sampler`
  // and `texture2D` are common names and functions elsewhere).
  static KeywordContext everything();
};

// A word's kind in `context`: a keyword kind, TokenKind::reserved_word, or
// TokenKind::identifier.
TokenKind classify_word(std::string_view word, const KeywordContext& context);

// "l_paren", "kw_float", "identifier": the enumerator's name (for dumps and tests).
std::string_view token_kind_name(TokenKind kind);
// "(", "float"; empty for kinds without a fixed spelling.
std::string_view token_kind_spelling(TokenKind kind);
// For messages: "'('", "'float'", "identifier", "end of file".
std::string_view token_kind_description(TokenKind kind);

bool is_keyword(TokenKind kind);
bool is_punctuator(TokenKind kind);
bool is_literal(TokenKind kind);  // numeric literals and true/false
bool is_numeric_literal(TokenKind kind);
KeywordCategory keyword_category(TokenKind kind);
inline bool is_type_keyword(TokenKind kind) { return keyword_category(kind) == KeywordCategory::type; }

struct Token {
  TokenKind kind = TokenKind::eof;
  bool at_line_start = false;   // first token on its line (after any #line/#include)
  bool leading_space = false;   // whitespace or a comment precedes it
  ExpansionId expansion = kNoExpansion;  // the macro expansion that produced it
  std::string_view text;        // spelling (line continuations removed)
  SourceRange range;            // where the spelling is: in the file, or in a #define body

  bool is(TokenKind k) const { return kind == k; }
  bool is_identifier(std::string_view word) const { return kind == TokenKind::identifier && text == word; }
};

// Splits a token that starts with '>' ('>>', '>=', '>>=') into a '>' and the
// rest, for the parser closing nested annotations (`sampler2D<float<length>>`).
// Returns nullopt for any other token.
std::optional<std::pair<Token, Token>> split_leading_greater(const Token& token);

// What a numeric literal's spelling (a C-style pp-number such as "1.5e3lf",
// "0x1Fu" or "1D") means: its kind, and the error if it is not a valid GLSL
// literal; error_begin / error_end are byte offsets into the spelling.
struct NumericLiteralCheck {
  TokenKind kind = TokenKind::int_literal;
  std::string error;  // empty when valid
  std::uint32_t error_begin = 0;
  std::uint32_t error_end = 0;
};
NumericLiteralCheck check_numeric_literal(std::string_view spelling);

// Value of an integer literal's spelling (decimal, octal, hex; suffix
// ignored); nullopt when it does not fit in 64 bits or is malformed.
std::optional<std::uint64_t> integer_literal_value(std::string_view text);
// Value of a floating-point literal's spelling (suffix ignored).
double float_literal_value(std::string_view text);

}  // namespace safegi
