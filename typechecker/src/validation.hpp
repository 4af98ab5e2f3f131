#pragma once
// Shared vocabulary of the validating rules (validate_*.cpp): what GL drivers
// reject that the grammar allows — qualifiers out of place, layouts on the
// wrong declaration, built-ins of another version or stage, stage gates,
// l-values (docs/typechecker.md, "Validation").

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <safegi/lexer/extensions.hpp>
#include <safegi/parser/ast.hpp>

#include "safegi/typechecker/checker.hpp"

namespace safegi::detail {

// Where a feature exists: desktop GLSL from `desktop` on, GLSL ES from `es`
// on (0: never), or with any of `extensions` enabled.
struct VersionGate {
  int desktop = 0;
  int es = 0;
  std::initializer_list<const char*> extensions = {};
};

inline const VersionGate kBindlessGate{0, 0, {"GL_ARB_bindless_texture"}};

bool gate_allows(const VersionGate& gate, const LanguageLevel& level);
// "#version 150", "#version 300 es", "#version 400 or GL_ARB_gpu_shader5";
// "GL_EXT_gpu_shader4" when only an extension gives it.
std::string gate_requirement(const VersionGate& gate, bool es);

// The classes of qualifier words (GLSL 4.60 §4.3-4.10).
bool is_storage_word(std::string_view word);        // const in out inout attribute varying uniform buffer shared
bool is_ray_tracing_storage_word(std::string_view word);  // rayPayloadEXT … callableDataInNV
// The stage letters of a ray-tracing or mesh-shading storage qualifier; null for the others.
const char* stages_of_storage(std::string_view word);
// Vulkan GLSL's rules apply (safeglslc -V, or #extension GL_KHR_vulkan_glsl).
bool vulkan_glsl(const LanguageLevel* level);
bool is_auxiliary_word(std::string_view word);      // centroid sample patch
bool is_interpolation_word(std::string_view word);  // smooth flat noperspective (and the AMD/NV explicit ones)

// The first qualifier spelled `word`, or nullptr.
const ast::Qualifier* find_qualifier(const ast::TypeQualifiers& q, std::string_view word);
// The first layout identifier `id` in any layout(...) of `q`, or nullptr.
const ast::LayoutId* find_layout_id(const ast::TypeQualifiers& q, std::string_view id);

// Samplers, images and atomic counters, or a struct holding one (not
// Vulkan's or ray tracing's opaque types, which have rules of their own).
bool contains_opaque(const Type& t);
// `t` is of scalar type `scalar` (bool, double, …) or a struct holding one.
bool contains_scalar(const Type& t, Scalar scalar);
// Bytes of the widest scalar in `t` (its struct members' included); 0 for none.
int widest_scalar_bytes(const Type& t);

// The value of a gl_Max constant the rules need (glslang's default resource limits), or nothing.
std::optional<long long> builtin_constant(std::string_view name);

// A built-in variable of some stage (builtin_variables.def), gl_in, gl_out.
bool known_builtin_variable(std::string_view name);

// The letters of builtin_variables.def and builtin_availability.def: v c e g f x ('*' for unknown).
char stage_letter(Stage stage);
// "vertex", "vertex and geometry", "vertex, geometry and fragment" for a string of stage letters.
std::string stage_list(std::string_view letters);

// Where a layout qualifier stands, for the rules of validate_layouts.cpp.
struct LayoutSite {
  enum class Kind : std::uint8_t { variable, block, member, standalone };
  Kind kind = Kind::variable;
  std::string storage;                           // in out uniform buffer shared attribute varying, or ""
  const Type* type = nullptr;                    // the declared type of a variable or member
  std::string name;                              // the variable's name (gl_FragCoord, gl_FragDepth redeclarations)
  const ast::InterfaceBlockDecl* block = nullptr;  // a member's block
};

// One input or output's locations (GLSL 4.60 §4.4.1): slots [first, last], components [first_component, last_component].
struct LocationUse {
  bool output = false;
  long long first = 0, last = 0;
  int first_component = 0, last_component = 3;
  std::string name;
  SourceRange range;
};

// What the validating rules remember across declarations.
struct ValidationState {
  std::unordered_map<const ast::LayoutId*, std::optional<long long>> layout_values;  // evaluated once
  // Stage-wide layouts every declaration must agree on: max_vertices, vertices, invocations, local_size_x, ...,
  // "input primitive", "output primitive", "xfb_stride of buffer N".
  std::map<std::string, std::pair<long long, SourceRange>> stage_layouts;
  std::vector<LocationUse> locations;
  long long default_xfb_buffer = 0;           // from `layout(xfb_buffer = N) out;`
  std::unordered_map<std::string, SourceRange> readonly_members;  // "instance.member" of named buffer blocks
  std::unordered_map<std::string, SourceRange> per_vertex_outputs;  // a tessellation control shader's (not `patch`)
  std::unordered_map<std::string, SourceRange> used_builtins;  // built-in variables read or written so far
  std::optional<std::pair<std::string, SourceRange>> frag_coord_layout;  // the first gl_FragCoord redeclaration
  int flow_depth = 0;                          // if / loop / switch statements around the statement being checked
  const void* returned_from = nullptr;         // the function (`main`) a return statement was seen in
  std::map<std::string, SourceRange> called_once;  // beginInvocationInterlockARB / endInvocationInterlockARB
  std::string uniform_packing = "shared";     // `layout(std140) uniform;`
  std::string buffer_packing = "shared";
};

}  // namespace safegi::detail
