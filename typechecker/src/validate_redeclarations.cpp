// Redeclared built-in variables (GLSL 4.60 §7.1, GLSL 1.30 §7.2,
// GL_ARB_fragment_coord_conventions): gl_ClipDistance, gl_CullDistance and
// gl_TexCoord keep their storage and element type and may only be sized (up
// to the implementation's maximum); gl_FragCoord is redeclared before any use,
// each time with the same layout.

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

struct SizedBuiltin {
  const char* name;
  const char* element;  // its element type's GLSL name
  const char* maximum;  // the gl_Max constant that bounds its size
};

constexpr SizedBuiltin kSizedBuiltins[] = {
    {"gl_ClipDistance", "float", "gl_MaxClipDistances"},
    {"gl_CullDistance", "float", "gl_MaxCullDistances"},
    {"gl_TexCoord", "vec4", "gl_MaxTextureCoords"},
};

std::string layout_words(const ast::TypeQualifiers& q) {
  std::string words;
  for (const char* id : {"origin_upper_left", "pixel_center_integer"})
    if (find_layout_id(q, id)) words += (words.empty() ? "" : ", ") + std::string(id);
  return words.empty() ? "no layout" : "layout(" + words + ")";
}

}  // namespace

// glslang's default resource limits for the gl_Max constants the rules need
// (piglit's tests size against the constants, not against numbers).
std::optional<long long> builtin_constant(std::string_view name) {
  static constexpr std::pair<std::string_view, long long> kConstants[] = {
      {"gl_MaxClipDistances", 8},
      {"gl_MaxCullDistances", 8},
      {"gl_MaxTextureCoords", 32},
      {"gl_MaxTransformFeedbackBuffers", 4},
      {"gl_MaxTransformFeedbackInterleavedComponents", 64},
      {"gl_MaxGeometryOutputVertices", 256},
      {"gl_MaxPatchVertices", 32},
  };
  for (const auto& [n, v] : kConstants)
    if (n == name) return v;
  return std::nullopt;
}

void Checker::validate_builtin_redeclaration(const ast::VariableDecl& d, const ast::Declarator& decl, const Type& type) {
  const std::string& name = decl.name;
  if (name == "gl_FragCoord") {
    if (validation_.used_builtins.count(name) && !validation_.frag_coord_layout) {
      reject(decl.name_range, "gl_FragCoord must be redeclared before it is used", code::E_REDECLARATION);
      return;
    }
    const std::string layout = layout_words(d.qualifiers);
    if (!validation_.frag_coord_layout) {
      validation_.frag_coord_layout = std::pair{layout, decl.name_range};
    } else if (validation_.frag_coord_layout->first != layout) {
      report(Diagnostic::error(decl.name_range, "gl_FragCoord is redeclared with " + layout + ", but was with " +
                                                    validation_.frag_coord_layout->first + " before; every redeclaration must agree")
                 .with_code(code::E_REDECLARATION)
                 .with_note(Diagnostic::note(validation_.frag_coord_layout->second, "the first redeclaration is here")));
    }
    return;
  }
  for (const SizedBuiltin& b : kSizedBuiltins) {
    if (name != b.name || type.is_error()) continue;
    const bool fragment = options_.stage == Stage::fragment;
    const char* storage = fragment ? "in" : "out";
    const bool storage_ok = d.qualifiers.has(storage) || d.qualifiers.has("varying");
    const bool only_storage = !d.qualifiers.has("uniform") && !d.qualifiers.has("const") &&
                              !(fragment ? d.qualifiers.has("out") : d.qualifiers.has("in"));
    if (!storage_ok || !only_storage) {
      reject(decl.name_range, "'" + name + "' can only be redeclared as an '" + storage + "' of a " + stage_name(options_.stage) +
                                  " shader",
             code::E_REDECLARATION, "write '" + std::string(storage) + " " + b.element + " " + name + "[N];'");
      return;
    }
    if (!type.is_array() || glsl_name(type.element()) != b.element) {
      reject(decl.name_range, "'" + name + "' is redeclared as " + glsl_name(type) + "; it must stay an array of " + b.element,
             code::E_REDECLARATION);
      return;
    }
    const long long maximum = *builtin_constant(b.maximum);
    if (type.array[0] > maximum) {
      reject(decl.name_range, "'" + name + "' is redeclared with " + std::to_string(type.array[0]) +
                                  " elements; it may have at most " + b.maximum + " (" + std::to_string(maximum) + ")",
             code::E_REDECLARATION);
    }
    return;
  }
}

}  // namespace safegi::detail
