#pragma once
// The type checker: GLSL's own type rules plus SafeGI's dimension and space
// analysis over the parser's AST (docs/typechecker.md).
//
//   DiagnosticEngine diags;
//   CheckResult r = check(unit, CheckOptions{.stage = Stage::fragment}, diags);
//
// Every diagnostic goes to the engine; the result describes every declaration
// and expression (for the elider) and the interface variables (for the symbol
// table), and is complete even when there were errors (erroneous expressions
// have the error type).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/extensions.hpp>
#include <safegi/lexer/token.hpp>
#include <safegi/parser/ast.hpp>

#include "safegi/dimension_algebra/registry.hpp"
#include "safegi/typechecker/type.hpp"

namespace safegi {

// The stages of stages.def, in pipeline order, then `unknown`.
enum class Stage : std::uint8_t {
#define SAFEGI_STAGE(id, ...) id,
#include "safegi/symbol_table/stages.def"
  unknown
};

// How stages exchange data: by in/out between neighbours (graphics), not at
// all (compute), by payloads and hit attributes (ray tracing), by a task
// payload and per-vertex / per-primitive outputs (mesh).
enum class StageFamily : std::uint8_t { graphics, compute, ray_tracing, mesh };

struct StageInfo {
  Stage stage;
  char letter;                 // builtin_variables.def's and builtin_availability.def's letter
  const char* extension;       // file extension and -S name: "rgen"
  const char* long_name;       // the other -S name: "raygen"
  const char* words;           // "ray generation"
  StageFamily family;
};

// Every stage (stages.def), in pipeline order.
const std::vector<StageInfo>& stage_table();
const StageInfo* stage_info(Stage stage);  // null for Stage::unknown

// "vertex", "tessellation control", …, "ray generation" ("unknown" for Stage::unknown).
const char* stage_name(Stage stage);

struct CheckOptions {
  Stage stage = Stage::unknown;  // selects the built-in variables (gl_Position, gl_FragCoord, …)
  bool strict = false;           // warn on unannotated interface variables and on `?` flowing into annotations
  // The shader's #version and extensions (PreprocessedUnit::language): the
  // validating rules that depend on them (stage gates, built-ins of later
  // versions, qualifiers a version does not have; docs/typechecker.md) run
  // only when it is set. Unset: every version's rules are off.
  std::optional<LanguageLevel> language;
  SourceRange version_range;  // the #version line (PreprocessedUnit::version_range), where stage gates point
  // The preprocessed tokens the tree was parsed from and their SourceManager
  // (optional, both or neither): diagnostics inside macro expansions then get
  // their "in expansion of macro X" notes.
  const std::vector<Token>* tokens = nullptr;
  const SourceManager* sources = nullptr;
  // Record CheckResult::symbols (editors: hover, go to definition). Off by
  // default: a compilation for a driver does not pay for it.
  bool record_symbols = false;
};

// ray_payload / ray_payload_in: rayPayloadEXT and rayPayloadInEXT variables (and NV), no host's business.
enum class InterfaceKind : std::uint8_t { uniform, input, output, buffer, shared, ray_payload, ray_payload_in };

struct InterfaceVariable {
  InterfaceKind kind = InterfaceKind::uniform;
  std::string name;        // `block.member` for members of an instance-named block
  std::string block;       // the block name when a block member
  Type type;               // annotated type (arrays included)
  std::string type_text;   // type_name(type), in the program's words
  SourceRange range;       // the declarator
  const ast::Node* decl = nullptr;
  int location = -1;       // layout(location = N), -1 when absent
  int binding = -1;        // layout(binding = N), -1 when absent
  int set = -1;            // layout(set = N), Vulkan's descriptor set, -1 when absent
  bool push_constant = false;  // a member of a layout(push_constant) block (Vulkan)
  bool shader_record = false;  // a member of a layout(shaderRecordEXT) block: the shader binding table's data
  bool annotated = false;
};

// Where a block member lies in memory, in bytes from the block's start (GLSL
// 4.60 §7.6.2.2 for std140 and std430, GL_EXT_scalar_block_layout for scalar,
// explicit offset and align included): what a host writes a uniform buffer,
// storage buffer or push-constant range by.
struct MemberLayout {
  long long offset = 0;
  long long size = -1;          // -1: a runtime-sized array (array_stride says how its elements lie)
  long long array_stride = 0;   // arrays: bytes from one element to the next
  long long matrix_stride = 0;  // matrices and arrays of them: bytes from one column (row_major: row) to the next
  bool row_major = false;
  std::vector<MemberLayout> fields;  // a struct's (or an array of structs'), from the start of the struct
};

struct BlockLayout {
  std::string packing;  // "std140", "std430" or "scalar" (shared and packed blocks have none)
  long long size = -1;  // the end of the last member; -1 when that is a runtime-sized array
  std::unordered_map<const ast::Declarator*, MemberLayout> members;
};

// `layout(constant_id = N) const T name = value;` and `layout(local_size_x_id = N) in;`
// (Vulkan, GL_ARB_gl_spirv): a value the host may set when it creates the pipeline.
struct SpecializationConstant {
  std::string name;  // the constant, or gl_WorkGroupSize.x/.y/.z for local_size_*_id
  int id = 0;
  Type type;
  std::string type_text;
  SourceRange range;
  std::optional<long long> integer_value;  // the declared default, when the checker knows it
  std::optional<double> float_value;
};

// How a geometric operation must be emitted (the elider's business).
enum class GeometricOp : std::uint8_t {
  none,
  transform_point,      // map * point: (m * vec4(p, 1)).xyz
  transform_vector,     // map * vector / direction: mat3(m) * v
  transform_normal,     // map * normal: transpose(inverse(mat3(m))) * n
  project,              // projmap * point: m * vec4(p, 1)
  transform_homogeneous,  // map or projmap * hpoint: m * h
  homogenize,           // h.xyz / h.w
  inverse_square,       // 1.0 / (d * d)
  compose,              // m2 * m1
  inverse,              // inverse(m)
};

// How a conversion `e in target` is emitted (the elider's business).
struct ConversionInfo {
  double factor = 1.0;            // a unit conversion: e * factor (1: nothing to emit)
  std::vector<std::string> maps;  // a space conversion: the maps, as written (the last applied is leftmost)
  GeometricOp op = GeometricOp::none;  // how the composed maps apply: transform_point/vector/normal, project
};

struct CallInfo {
  std::string builtin;          // built-in name when a built-in was called
  std::string signature;        // the chosen signature as text
  GeometricOp op = GeometricOp::none;
};

// What a name written in the program stands for (CheckOptions::record_symbols).
enum class SymbolKind : std::uint8_t {
  variable,             // globals, locals, parameters, interface variables, members of blocks without instance name
  field,                // a struct or block member, where declared and where reached through '.'
  function,             // a user function
  structure,            // a struct name
  builtin_variable,     // gl_Position, ...
  builtin_function,     // dot, transform, ... (the table's signature in type_text)
  dimension,            // base or derived dimension
  unit,
  space,
  dimension_parameter,  // template<dimension D>
  space_parameter,      // template<space S>
};
const char* symbol_kind_name(SymbolKind kind);  // "variable", "field", ..., "space parameter"

// One occurrence of a name: each declaration and each use.
struct SymbolOccurrence {
  SymbolKind kind = SymbolKind::variable;
  std::string name;
  SourceRange range;          // the name as written here (for a token from a macro: in the #define)
  SourceRange declaration;    // the name in its (first) declaration; invalid for built-ins
  bool is_declaration = false;
  // Variables and fields: their type; functions: the result at this call (the
  // declared one at the declaration); units and dimensions: float<D>.
  Type type;
  // In the program's words (template parameters by name); for functions the
  // whole declaration, `template<dimension D> float<D> f(float<D> x)`.
  std::string type_text;
};

struct CheckResult {
  Stage stage = Stage::unknown;                                  // CheckOptions::stage
  DimensionRegistry registry;                                    // the program's declarations (and the prelude it included)
  std::unordered_map<const ast::Node*, Type> types;              // every expression and parameter
  std::unordered_map<const ast::Declarator*, Type> declarators;  // every declared variable (locals inferred from initialisers)
  std::unordered_map<const ast::Node*, CallInfo> calls;          // calls and operators that are geometric operations
  std::unordered_map<const ast::ConvertExpr*, ConversionInfo> conversions;  // every `e in target` that checked
  std::vector<InterfaceVariable> interface;                      // uniforms (incl. block members), inputs, outputs, buffers
  std::unordered_map<const ast::InterfaceBlockDecl*, BlockLayout> block_layouts;  // uniform and buffer blocks of a known layout
  std::vector<SpecializationConstant> specialization_constants;  // in declaration order
  std::vector<std::unique_ptr<StructInfo>> structs;              // owned: Type::structure points here
  std::vector<SymbolOccurrence> symbols;                         // only with CheckOptions::record_symbols, in checking order

  const Type* type_of(const ast::Node* node) const;
  const Type* type_of(const ast::Declarator* declarator) const;
  std::string describe(const Type& t) const { return type_name(t, registry); }
};

CheckResult check(const ast::TranslationUnit& unit, const CheckOptions& options, DiagnosticEngine& diagnostics);

// Cross-stage matching (GLSL 4.40 §4.4.1 interface matching): each input of
// `consumer` is matched to an output of `producer` by location when it has a
// `layout(location = N)` (else by name); members of interface blocks are
// matched by block name and member name, whatever the instance names. Matched
// pairs must have the identical annotated type (the per-vertex array level of
// geometry and tessellation inputs, and of tessellation-control outputs, is
// not part of the comparison); a mismatch is one error at the input with a
// note at the output, both types in the program's words.
void check_interface_match(const CheckResult& producer, const CheckResult& consumer, DiagnosticEngine& diagnostics);
// Ray tracing: the payload a closest-hit, any-hit or miss shader receives
// (rayPayloadInEXT) must have the type, dimension and spaces included, of a
// payload the ray generation shader traces (rayPayloadEXT at some location):
// which one a ray reaches depends on the shader binding table, so any will do.
void check_payload_match(const CheckResult& tracer, const CheckResult& receiver, DiagnosticEngine& diagnostics);

}  // namespace safegi
