// Qualifiers where GLSL does not allow them: how many of each kind a
// declaration may have and in which order, what locals, struct members and
// parameters may carry, names reserved for the implementation, opaque types
// outside uniforms, and precision statements (GLSL 4.60 §4.3-4.7, §3.8; the
// older orders of GLSL 1.30-4.10; Mesa's behaviour where they differ).

#include <cstring>
#include <string>
#include <vector>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

const VersionGate kAnyQualifierOrder{420, 310, {"GL_ARB_shading_language_420pack"}};

// A qualifier's place in the order GLSL 1.30-4.10 require: invariant,
// interpolation, auxiliary (centroid), storage, precision. Layouts, memory
// qualifiers and `precise` are not ordered.
// Interpolation and auxiliary qualifiers may come in either order
// (`centroid noperspective varying`, GL_EXT_gpu_shader4).
int order_rank(const ast::Qualifier& q) {
  if (q.kind == ast::QualifierKind::Invariant) return 0;
  if (q.kind == ast::QualifierKind::Interpolation || is_auxiliary_word(q.word)) return 1;
  if (is_storage_word(q.word)) return 2;
  if (q.kind == ast::QualifierKind::Precision) return 3;
  return -1;
}

const char* kRankWords[] = {"'invariant'", "interpolation and auxiliary qualifiers", "storage qualifiers",
                            "precision qualifiers"};

bool reserved_name(const std::string& name) { return name.rfind("gl_", 0) == 0; }

}  // namespace

// A ray-tracing or mesh-shading storage qualifier of a stage other than this one.
const ast::Qualifier* Checker::storage_of_another_stage(const ast::TypeQualifiers& q) const {
  const char letter = stage_letter(options_.stage);
  if (letter == '*') return nullptr;
  for (const ast::Qualifier& x : q.list)
    if (const char* stages = stages_of_storage(x.word); stages && !std::strchr(stages, letter)) return &x;
  return nullptr;
}

namespace {

}  // namespace

// At most one storage, one auxiliary and one interpolation qualifier, and
// before GLSL 4.20 (GL_ARB_shading_language_420pack) in the order invariant,
// interpolation, auxiliary, storage, precision. `varying in` / `varying out`
// (GL_ARB_geometry_shader4, GL_EXT_gpu_shader4) and a parameter's `const in`
// are the two storage pairs GLSL has.
// Returns false when it reported an error.
static bool check_qualifier_counts(Checker& c, const ast::TypeQualifiers& q, bool parameter) {
  if (!c.memory_model_qualifiers(q)) return false;
  // spirv_decorate_id(..., x): x names a variable or constant declared before.
  for (const ast::Qualifier& x : q.list) {
    if (x.kind != ast::QualifierKind::Spirv || x.word != "spirv_decorate_id") continue;
    for (const ast::SpirvArg& arg : x.spirv_args) {
      const auto* name = ast::dyn_cast<ast::IdentifierExpr>(arg.value);
      if (arg.kind != ast::SpirvArg::Kind::Value || !name || c.lookup(name->name)) continue;
      c.reject(name->range, "use of undeclared identifier '" + name->name + "' in 'spirv_decorate_id(...)'",
               code::E_UNDECLARED);
      return false;
    }
  }
  const ast::Qualifier* storage = nullptr;
  const ast::Qualifier* auxiliary = nullptr;
  const ast::Qualifier* interpolation = nullptr;
  const ast::Qualifier* invariant = nullptr;
  const ast::Qualifier* precision = nullptr;
  for (const ast::Qualifier& x : q.list) {
    const ast::Qualifier** slot = nullptr;
    const char* what = nullptr;
    if (is_storage_word(x.word)) {
      const bool pair = storage && ((storage->word == "varying" && (x.word == "in" || x.word == "out")) ||
                                    ((x.word == "varying") && (storage->word == "in" || storage->word == "out")) ||
                                    (parameter && storage->word == "const" && x.word == "in") ||
                                    (parameter && storage->word == "in" && x.word == "const"));
      if (pair) continue;
      slot = &storage;
      what = "storage qualifier";
    } else if (is_auxiliary_word(x.word)) {
      // GL_NV_mesh_shader: a per-view output may also be per-primitive (`perviewNV perprimitiveNV out vec4 v[][];`).
      const bool view_and_primitive = auxiliary && ((auxiliary->word == "perviewNV" && x.word == "perprimitiveNV") ||
                                                    (auxiliary->word == "perprimitiveNV" && x.word == "perviewNV"));
      if (view_and_primitive) continue;
      slot = &auxiliary;
      what = "auxiliary qualifier (centroid, sample, patch)";
    } else if (x.kind == ast::QualifierKind::Interpolation) {
      slot = &interpolation;
      what = "interpolation qualifier (smooth, flat, noperspective)";
    } else if (x.kind == ast::QualifierKind::Invariant) {
      slot = &invariant;
      what = "'invariant'";
    } else if (x.kind == ast::QualifierKind::Precision) {
      slot = &precision;
      what = "precision qualifier";
    }
    if (!slot) continue;
    if (*slot) {
      const bool same = (*slot)->word == x.word;
      if (parameter && slot == &storage && ((*slot)->word == "const" || x.word == "const") && !same) {
        const std::string& other = (*slot)->word == "const" ? x.word : (*slot)->word;
        c.reject(x.range, "a 'const' parameter cannot be '" + other + "': it could not be written", code::E_QUALIFIER);
        return false;
      }
      c.reject(x.range,
               same ? "'" + x.word + "' is given twice"
                    : std::string("a declaration takes at most one ") + what + ": '" + (*slot)->word + "' and '" + x.word + "'",
               code::E_QUALIFIER);
      return false;
    }
    *slot = &x;
  }
  if (c.allows(kAnyQualifierOrder)) return true;
  int highest = -1;
  const ast::Qualifier* previous = nullptr;
  for (const ast::Qualifier& x : q.list) {
    const int rank = order_rank(x);
    if (rank < 0) continue;
    if (rank < highest) {
      c.reject(x.range,
               "'" + x.word + "' must come before '" + previous->word + "': before #version 420 (or " +
                   "GL_ARB_shading_language_420pack) the order is invariant, interpolation, storage, precision",
               code::E_QUALIFIER_ORDER, std::string(kRankWords[rank]) + " come before " + kRankWords[highest]);
      return false;
    }
    highest = rank;
    previous = &x;
  }
  return true;
}

// The Vulkan memory model's coherence qualifiers (devicecoherent, queuefamilycoherent, workgroupcoherent,
// subgroupcoherent, nonprivate) need GL_KHR_memory_scope_semantics, shadercallcoherent GL_EXT_ray_tracing;
// they are keywords wherever `coherent` is (glslang).
bool Checker::memory_model_qualifiers(const ast::TypeQualifiers& q) {
  const LanguageLevel* level = language();
  if (!level) return true;
  for (const ast::Qualifier& x : q.list) {
    if (x.kind != ast::QualifierKind::Memory) continue;
    const char* need = x.word == "shadercallcoherent" ? "GL_EXT_ray_tracing"
                       : x.word == "devicecoherent" || x.word == "queuefamilycoherent" || x.word == "workgroupcoherent" ||
                               x.word == "subgroupcoherent" || x.word == "nonprivate"
                           ? "GL_KHR_memory_scope_semantics"
                           : nullptr;
    if (!need || level->extension_enabled(need)) continue;
    reject(x.range, "'" + x.word + "' requires " + need, code::E_VERSION, "enable it with '#extension " + std::string(need) + " : enable'");
    return false;
  }
  return true;
}

void Checker::validate_variable(const ast::VariableDecl& d, const Type& base, bool global) {
  const ast::TypeQualifiers& q = d.qualifiers;
  if (!check_qualifier_counts(*this, q, false)) return;
  if (d.type && d.type->form == ast::TypeSpecifier::Form::Struct && d.type->struct_decl)
    validate_struct_members(*d.type->struct_decl);
  if (!global) {
    // GLSL 4.60 §4.3: local variables take only `const` (and precision, precise); GL_EXT_nonuniform_qualifier
    // adds `nonuniformEXT` (its keyword exists only with the extension).
    for (const ast::Qualifier& x : q.list) {
      const bool allowed = x.word == "const" || x.word == "nonuniformEXT" || x.kind == ast::QualifierKind::Precision ||
                           x.kind == ast::QualifierKind::Precise ||
                           (x.kind == ast::QualifierKind::Memory && allows(kBindlessGate)) ||  // image handles in locals
                           // a reference's memory (GL_EXT_buffer_reference): `nonprivate Ref r = …;`
                           (x.kind == ast::QualifierKind::Memory && base.shape == Shape::structure && base.structure &&
                            base.structure->buffer_reference);
      if (allowed) continue;
      const std::string what = x.kind == ast::QualifierKind::Layout ? std::string("layout qualifiers") : "'" + x.word + "'";
      reject(x.range, what + " cannot qualify a local variable; locals take only 'const', 'precise' and a precision",
             code::E_QUALIFIER);
      return;
    }
  } else if (const ast::Qualifier* misplaced = storage_of_another_stage(q)) {
    reject(misplaced->range, "'" + misplaced->word + "' variables belong to " + stage_list(stages_of_storage(misplaced->word)) +
                                 " shaders, not to " + stage_name(options_.stage) + " shaders",
           code::E_QUALIFIER);
    return;
  } else if (const ast::Qualifier* inout = find_qualifier(q, "inout")) {
    reject(inout->range, "'inout' qualifies only function parameters, not global variables", code::E_QUALIFIER,
           "an output of this stage is 'out', an input 'in'");
    return;
  }
  for (const ast::Declarator& decl : d.declarators) {
    if (reserved_name(decl.name) && !lookup(decl.name) && !known_builtin_variable(decl.name) && !spirv_intrinsics()) {
      reject(decl.name_range, "'" + decl.name + "' is not a built-in variable here, and names beginning with 'gl_' are reserved",
             code::E_RESERVED_NAME);
      return;
    }
  }
  // Opaque types (samplers, images, atomic counters) live in uniforms and parameters only.
  if (!d.declarators.empty() && contains_opaque(base) && !q.has("uniform") && !allows(kBindlessGate)) {
    const SourceRange where = d.declarators.empty() ? d.range : d.declarators.front().name_range;
    const std::string what = base.shape == Shape::opaque ? "'" + base.opaque + "'" : "a struct with an opaque member";
    reject(where, "a variable of " + what + " type must be 'uniform' (or a function parameter)", code::E_OPAQUE);
  }
}

void Checker::validate_struct_members(const ast::StructDecl& s) {
  if (reserved_name(s.name)) {
    reject(s.name_range, "struct name '" + s.name + "' begins with 'gl_', which is reserved", code::E_RESERVED_NAME);
    return;
  }
  for (const ast::VariableDecl* member : s.members) {
    if (member->type && member->type->form == ast::TypeSpecifier::Form::Struct) {
      reject(member->type->range, "a struct definition cannot be nested inside another struct", code::E_QUALIFIER,
             "define the inner struct at global scope and use its name");
      return;
    }
    // GLSL 4.60 §4.1.8: "Member declarators may contain precision qualifiers, but use of any other qualifier results
    // in a compile-time error." Block layouts on members are the parser's (reported there).
    for (const ast::Qualifier& x : member->qualifiers.list) {
      if (x.kind == ast::QualifierKind::Precision) continue;
      if (x.kind == ast::QualifierKind::Memory && allows(kBindlessGate)) continue;  // image handles in structs
      if (x.kind == ast::QualifierKind::Layout) {
        bool parser_reports = false;
        for (const ast::LayoutId& id : x.layout_ids)
          parser_reports = parser_reports || id.name == "std140" || id.name == "std430" || id.name == "shared" ||
                           id.name == "packed" || id.name == "row_major" || id.name == "column_major";
        if (parser_reports) continue;
      }
      const std::string what = x.kind == ast::QualifierKind::Layout ? std::string("layout qualifiers") : "'" + x.word + "'";
      reject(x.range, what + " cannot qualify a struct member; members take only a precision qualifier", code::E_QUALIFIER);
      return;
    }
  }
}

void Checker::validate_function(const ast::FunctionDecl& d, const Function& f) {
  if (reserved_name(d.name)) {
    reject(d.name_range, "function name '" + d.name + "' begins with 'gl_', which is reserved", code::E_RESERVED_NAME);
    return;
  }
  const bool bindless = allows(kBindlessGate);
  if (!bindless && contains_opaque(f.result) && d.return_type) {
    reject(d.return_type->range, "a function cannot return an opaque type ('" + glsl_name(f.result) + "')", code::E_OPAQUE);
    return;
  }
  if (d.name == "main" && d.template_params.empty()) {
    if (f.result.shape != Shape::void_ && !f.result.is_error() && d.return_type) {
      reject(d.return_type->range, "'main' must return void", code::E_MAIN);
      return;
    }
    if (!d.params.empty()) {
      reject(d.params.front()->range, "'main' takes no parameters", code::E_MAIN);
      return;
    }
  }
  for (std::size_t i = 0; i < d.params.size(); ++i) {
    const ast::ParamDecl& p = *d.params[i];
    const ast::TypeQualifiers& q = p.qualifiers;
    if (!check_qualifier_counts(*this, q, true)) return;
    for (const ast::Qualifier& x : q.list) {
      const bool allowed = x.word == "const" || x.word == "in" || x.word == "out" || x.word == "inout" ||
                           x.kind == ast::QualifierKind::Precision || x.kind == ast::QualifierKind::Precise ||
                           x.kind == ast::QualifierKind::Memory || x.word == "spirv_by_reference" ||
                           x.word == "spirv_literal";
      if (allowed) continue;
      const std::string what = x.kind == ast::QualifierKind::Layout ? std::string("layout qualifiers") : "'" + x.word + "'";
      reject(x.range, what + " cannot qualify a function parameter; parameters take const, in, out, inout, precise, "
                             "memory and precision qualifiers",
             code::E_QUALIFIER);
      return;
    }
    const ast::Qualifier* out = find_qualifier(q, "out");
    if (!out) out = find_qualifier(q, "inout");
    if (out && !bindless && i < f.params.size() && contains_opaque(f.params[i])) {
      reject(out->range, "an opaque type ('" + glsl_name(f.params[i]) + "') cannot be an '" + out->word + "' parameter",
             code::E_OPAQUE);
      return;
    }
  }
}

void Checker::validate_precision(const ast::PrecisionDecl& d) {
  const Type t = resolve_type(d.type);
  if (t.is_error()) return;
  const bool ok = (t.shape == Shape::scalar && !t.is_array() && (t.scalar == Scalar::float_ || t.scalar == Scalar::int_)) ||
                  t.shape == Shape::opaque;
  if (!ok) {
    reject(d.type->range, "a default precision applies to 'float', 'int' and opaque types, not '" + glsl_name(t) + "'",
           code::E_PRECISION, t.shape == Shape::vector || t.shape == Shape::matrix ? "'precision " + d.precision +
                                                                                   " float;' covers vectors and matrices too"
                                                                             : "");
  }
}

}  // namespace safegi::detail

namespace safegi::detail {

// `invariant gl_Position;`, `precise p;`, `layout(local_size_x = 8) in;`.
void Checker::validate_qualifier_decl(const ast::QualifierDecl& d, bool global) {
  if (!check_qualifier_counts(*this, d.qualifiers, false)) return;
  if (global && d.qualifiers.has_layout_id("buffer_reference")) {  // `layout(buffer_reference) buffer Node;`
    for (const std::string& name : d.names) buffer_reference_type(name);
    return;
  }
  if (global) {
    validate_default_layouts(d);
    return;
  }
  for (const ast::Qualifier& x : d.qualifiers.list) {
    if (x.kind == ast::QualifierKind::Precise) continue;
    const std::string what = x.kind == ast::QualifierKind::Layout ? std::string("a layout qualifier") : "'" + x.word + "'";
    reject(x.range, what + " can be applied to existing variables only at global scope", code::E_QUALIFIER);
    return;
  }
}

}  // namespace safegi::detail
