// Built-in functions and variables by version, stage and profile
// (builtin_availability.def): `texture()` before 1.30, `dFdx` in a vertex
// shader, `gl_Vertex` in a core profile, `gl_InstanceIDARB` without its
// extension.

#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

enum class Profile : std::uint8_t { any, compat, legacy };

struct Availability {
  const char* name;
  int desktop;
  int es;
  const char* stages;
  const char* extensions;
  Profile profile;
};

constexpr Availability kAvailability[] = {
#define AVAILABLE(name, desktop, es, stages, extensions, profile) {#name, desktop, es, stages, extensions, Profile::profile},
#include "builtin_availability.def"
#undef AVAILABLE
};

const Availability* find_availability(std::string_view name) {
  static const std::unordered_map<std::string_view, const Availability*> index = [] {
    std::unordered_map<std::string_view, const Availability*> m;
    for (const Availability& a : kAvailability) m.emplace(a.name, &a);
    return m;
  }();
  auto it = index.find(name);
  return it == index.end() ? nullptr : it->second;
}

// The extensions of a row that apply to desktop GLSL (`es` false) or to GLSL
// ES: an `es:` prefix marks one of GLSL ES alone.
std::vector<std::string_view> extensions_for(const char* extensions, bool es) {
  std::vector<std::string_view> out;
  std::string_view list = extensions;
  while (!list.empty()) {
    const std::size_t space = list.find(' ');
    std::string_view e = list.substr(0, space);
    const bool es_only = e.rfind("es:", 0) == 0;
    if (es_only) e.remove_prefix(3);
    if (!e.empty() && (es || !es_only)) out.push_back(e);
    if (space == std::string_view::npos) break;
    list.remove_prefix(space + 1);
  }
  return out;
}

std::string version_text(int version, bool es) { return "#version " + std::to_string(version) + (es ? " es" : ""); }

}  // namespace

bool Checker::builtin_available(const std::string& name, SourceRange where, bool function) {
  if (!function) validation_.used_builtins.emplace(name, where);  // gl_FragCoord's redeclaration comes first
  const Availability* a = find_availability(name);
  if (!a) return true;
  const LanguageLevel* level = language();
  const char letter = stage_letter(options_.stage);
  if (function && *a->stages && letter != '*' && !std::strchr(a->stages, letter)) {
    // GL_NV_compute_shader_derivatives brings the derivatives (and textureQueryLod) to compute shaders.
    const bool derivative = name.rfind("dFd", 0) == 0 || name.rfind("fwidth", 0) == 0 || name.rfind("textureQueryL", 0) == 0;
    const bool compute_derivatives =
        letter == 'x' && derivative && level && level->extension_enabled("GL_NV_compute_shader_derivatives");
    if (!compute_derivatives) {
      reject(where, "'" + name + "' is not available in " + stage_name(options_.stage) + " shaders", code::E_STAGE_BUILTIN,
             "'" + name + "' is a built-in of " + stage_list(a->stages) + " shaders");
      return false;
    }
  }
  if (!level) return true;
  const std::vector<std::string_view> extensions = extensions_for(a->extensions, level->es);
  for (std::string_view e : extensions)
    if (level->extension_enabled(e)) return true;
  const std::string first = extensions.empty() ? "" : std::string(extensions.front());
  const int since = level->es ? a->es : a->desktop;
  const std::string here = version_text(level->version, level->es);
  const std::string enable = first.empty() ? "" : "enable it with '#extension " + first + " : enable'";
  if (since == 0 || level->version < since) {
    std::string need = since == 0 ? "" : version_text(since, level->es);
    if (!first.empty()) need += (need.empty() ? "" : " or ") + first;
    const std::string message = need.empty() ? "'" + name + "' is not available in " + std::string(level->es ? "GLSL ES" : "desktop GLSL")
                                              : "'" + name + "' requires " + need + "; the shader is " + here;
    // The GLSL 1.30 lookups have 1.10 names by sampler type.
    const bool new_lookup = function && since == 130 && !level->es && name.rfind("texture", 0) == 0;
    reject(where, message, code::E_VERSION,
           new_lookup ? "before #version 130 the lookups are named by sampler: texture2D, texture2DProj, textureCube, …" : enable);
    return false;
  }
  if (a->profile == Profile::any || compatibility_profile()) return true;
  if (a->profile == Profile::compat) {
    reject(where, "'" + name + "' belongs to the compatibility profile, which " + here + " does not have", code::E_VERSION,
           level->version < 150 ? "enable it with '#extension GL_ARB_compatibility : enable'"
                                : "use '#version " + std::to_string(level->version) + " compatibility', or declare a variable of your own");
    return false;
  }
  const bool removed = level->es ? level->version >= 300 : level->version >= 420;
  if (!removed) return true;
  const bool output = name == "gl_FragColor" || name == "gl_FragData";
  reject(where, "'" + name + "' was removed in " + (level->es ? "#version 300 es" : std::string("the core profile of #version 420")),
         code::E_VERSION, output ? "declare an output of your own, e.g. 'out vec4 color;'" : "use the overloaded names, e.g. 'texture'");
  return false;
}

}  // namespace safegi::detail
