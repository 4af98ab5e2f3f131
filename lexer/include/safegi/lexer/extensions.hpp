#pragma once
// GLSL extensions and version-gated language features, as data.
//
// known_extensions(): every extension whose syntax the front end parses, with
// the keyword groups it turns on (token_kinds.def); these are the extension
// macros a shader sees by default (`#ifdef GL_ARB_gpu_shader5`).
//
// LanguageFeature: syntax that exists only from some #version on or with an
// extension (`1.0lf`, arrays of arrays). LanguageLevel says what a shader's
// #version and #extension lines allow, and feature_requirement() words the
// diagnostic: "arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays".

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace safegi {

struct ExtensionInfo {
  std::string_view name;
  std::uint32_t keyword_groups = 0;  // bits (1 << ExtensionGroup)
};

// Vulkan GLSL: not an extension a GL driver advertises (no macro), but its
// #extension line, or Vulkan semantics (safeglslc -V), turn on its types and rules.
inline constexpr std::string_view kVulkanGlslExtension = "GL_KHR_vulkan_glsl";

// Sorted by name.
std::span<const ExtensionInfo> known_extensions();
const ExtensionInfo* find_extension(std::string_view name);
// Whether glslang knows an extension of this name (glslang_extensions.def): one
// neither it nor known_extensions() knows is what glslangValidator warns about
// (and refuses with `require`).
bool glslang_knows_extension(std::string_view name);
// The names of known_extensions(): PreprocessorOptions::extension_macros' default.
std::vector<std::string> default_extension_macros();
// For a type word of an extension (`float16_t`, `i64vec2`, `u64image2D`): the
// extensions that declare it, in words ("GL_EXT_shader_explicit_arithmetic_types_float16
// (or GL_EXT_shader_16bit_storage, ...)"); empty for other words.
std::string_view extensions_declaring_type(std::string_view word);

enum class LanguageFeature : std::uint8_t {
  double_literals,    // 1.0lf
  arrays_of_arrays,   // float a[2][3]
  global_in_out,      // `in` / `out` on global variables (1.10 has attribute and varying)
  integer_operators,  // % << >> & | ^ ~ and their assignments
  control_flow_attributes,  // [[unroll]] for (...) (GL_EXT_control_flow_attributes only)
  null_initializer,         // T x = {}; (GL_EXT_null_initializer only)
};

// The language a shader is written in: its #version and the extensions its
// #extension lines turned on (enable, require or warn; disable removes).
struct LanguageLevel {
  int version = 460;
  bool es = false;
  std::vector<std::string> extensions;
  bool compatibility = false;  // `#version 150 compatibility` (and later): the compatibility profile's built-ins

  bool extension_enabled(std::string_view name) const;
  bool allows(LanguageFeature feature) const;
  // Everything allowed: for callers that know no #version (tests, tools).
  static LanguageLevel everything();
};

// "arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays" (desktop)
// or "... require #version 310 es" (ES); "... are not available in GLSL ES".
std::string feature_requirement(LanguageFeature feature, bool es);

// Layout identifiers of later versions (`binding`, `offset`, `std430`, ...)
// and a layout value that is not a literal (constant expressions in layouts,
// GLSL 4.40): the error when `level` does not allow them, e.g.
// "layout(binding) requires #version 420 or GL_ARB_shading_language_420pack";
// empty when allowed or unknown (unknown identifiers are the checker's).
std::string layout_id_requirement(std::string_view id, const LanguageLevel& level);
std::string layout_expression_requirement(const LanguageLevel& level);

}  // namespace safegi
