// The validating rules' shared helpers (validation.hpp) and the checker's
// entry points into them.

#include "validation.hpp"

#include <algorithm>

#include "checker_impl.hpp"

namespace safegi::detail {

bool gate_allows(const VersionGate& gate, const LanguageLevel& level) {
  const int since = level.es ? gate.es : gate.desktop;
  if (since != 0 && level.version >= since) return true;
  return std::any_of(gate.extensions.begin(), gate.extensions.end(),
                     [&](const char* e) { return level.extension_enabled(e); });
}

std::string gate_requirement(const VersionGate& gate, bool es) {
  const int since = es ? gate.es : gate.desktop;
  std::string text = since != 0 ? "#version " + std::to_string(since) + (es ? " es" : "") : "";
  if (gate.extensions.size() != 0) text += (text.empty() ? "" : " or ") + std::string(*gate.extensions.begin());
  return text.empty() ? std::string(es ? "desktop GLSL" : "GLSL ES") : text;
}

bool is_storage_word(std::string_view w) {
  return w == "const" || w == "in" || w == "out" || w == "inout" || w == "attribute" || w == "varying" ||
         w == "uniform" || w == "buffer" || w == "shared" || is_ray_tracing_storage_word(w) || w == "taskPayloadSharedEXT";
}

bool is_ray_tracing_storage_word(std::string_view w) {
  return stages_of_storage(w) != nullptr && w != "taskPayloadSharedEXT";
}

// The stages each storage qualifier of ray tracing and mesh shading belongs to
// (GL_EXT_ray_tracing §4.3, GL_EXT_mesh_shader; glslang's "not supported in this stage").
const char* stages_of_storage(std::string_view w) {
  static constexpr std::pair<std::string_view, const char*> kStorages[] = {
      {"rayPayloadEXT", "rhs"},   {"rayPayloadNV", "rhs"},      {"rayPayloadInEXT", "ahs"},   {"rayPayloadInNV", "ahs"},
      {"hitAttributeEXT", "iah"}, {"hitAttributeNV", "iah"},    {"callableDataEXT", "rhsk"},  {"callableDataNV", "rhsk"},
      {"callableDataInEXT", "k"}, {"callableDataInNV", "k"},    {"taskPayloadSharedEXT", "tm"},
      {"hitObjectAttributeNV", "rhs"}};  // GL_NV_shader_invocation_reorder
  for (const auto& [word, stages] : kStorages)
    if (w == word) return stages;
  return nullptr;
}

bool vulkan_glsl(const LanguageLevel* level) { return level && level->extension_enabled(kVulkanGlslExtension); }

// perprimitive and perview (mesh shading) qualify an in or out as patch does.
bool is_auxiliary_word(std::string_view w) {
  return w == "centroid" || w == "sample" || w == "patch" || w == "perprimitiveEXT" || w == "perprimitiveNV" ||
         w == "perviewNV" || w == "taskNV";
}

bool is_interpolation_word(std::string_view w) {
  return w == "smooth" || w == "flat" || w == "noperspective" || w == "__explicitInterpAMD" || w == "pervertexNV" ||
         w == "pervertexEXT";
}

bool contains_opaque(const Type& t) {
  // A spirv_type (GL_EXT_spirv_intrinsics) may be any SPIR-V type: not held to the rules of samplers.
  if (t.shape == Shape::opaque && t.opaque.rfind("spirv_type", 0) == 0) return false;
  if (t.shape == Shape::opaque)
    return t.opaque.find("sampler") != std::string::npos || t.opaque.find("image") != std::string::npos ||
           t.opaque == "atomic_uint";
  if (t.shape == Shape::structure && t.structure && !t.structure->buffer_reference)  // a reference is an address
    for (const StructField& f : t.structure->fields)
      if (contains_opaque(f.type)) return true;
  return false;
}

bool contains_scalar(const Type& t, Scalar scalar) {
  if (t.shape == Shape::structure && t.structure && !t.structure->buffer_reference) {
    for (const StructField& f : t.structure->fields)
      if (contains_scalar(f.type, scalar)) return true;
    return false;
  }
  return t.scalar == scalar;
}

int widest_scalar_bytes(const Type& t) {
  if (t.shape == Shape::structure && t.structure && !t.structure->buffer_reference) {
    int widest = 0;
    for (const StructField& f : t.structure->fields) widest = std::max(widest, widest_scalar_bytes(f.type));
    return widest;
  }
  return t.scalar == Scalar::none ? 0 : scalar_bytes(t.scalar);
}

const ast::Qualifier* find_qualifier(const ast::TypeQualifiers& q, std::string_view word) {
  for (const ast::Qualifier& x : q.list)
    if (x.word == word) return &x;
  return nullptr;
}

const ast::LayoutId* find_layout_id(const ast::TypeQualifiers& q, std::string_view id) {
  for (const ast::Qualifier& x : q.list)
    for (const ast::LayoutId& l : x.layout_ids)
      if (l.name == id) return &l;
  return nullptr;
}

char stage_letter(Stage s) {
  const StageInfo* info = stage_info(s);
  return info ? info->letter : '*';
}

std::string stage_list(std::string_view letters) {
  std::string words;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    Stage stage = Stage::unknown;
    for (const StageInfo& s : stage_table())
      if (s.letter == letters[i]) stage = s.stage;
    words += std::string(i == 0 ? "" : i + 1 == letters.size() ? " and " : ", ") + stage_name(stage);
  }
  return words;
}

// GLSL 4.60 §4.3.3: literals, const variables with constant initializers,
// built-in constants, and operators, constructors and built-in functions
// over those; never assignments, ++/--, the comma operator or a call of a
// user function.
const ast::Expr* Checker::non_constant_part(const ast::Expr* e) const {
  if (!e) return nullptr;
  switch (e->kind) {
    case ast::NodeKind::LiteralExpr: return nullptr;
    case ast::NodeKind::IdentifierExpr: {
      const std::string& name = static_cast<const ast::IdentifierExpr*>(e)->name;
      const Variable* v = lookup(name);
      const bool builtin_constant = name == "gl_WorkGroupSize" || name == "gl_VerticesIn";
      if (v && !(v->builtin && builtin_constant)) return v->constant_expression ? nullptr : e;
      if (builtin_constant) return nullptr;
      if (result_.registry.find_unit(name)) return nullptr;  // a unit is a constant of its dimension
      if (name.rfind("gl_Max", 0) == 0 || name.rfind("gl_Min", 0) == 0) return nullptr;
      return e;
    }
    case ast::NodeKind::ParenExpr: return non_constant_part(static_cast<const ast::ParenExpr*>(e)->inner);
    case ast::NodeKind::UnaryExpr: {
      const auto* u = static_cast<const ast::UnaryExpr*>(e);
      if (u->op != ast::UnaryOp::Plus && u->op != ast::UnaryOp::Minus && u->op != ast::UnaryOp::Not &&
          u->op != ast::UnaryOp::BitNot)
        return e;
      return non_constant_part(u->operand);
    }
    case ast::NodeKind::BinaryExpr: {
      // GLSL ES 1.00 alone counts the comma operator as constant (Mesa, piglit's glsl-es-1.00 tests).
      const bool comma_constant = language() && language()->es && language()->version < 300;
      const auto* b = static_cast<const ast::BinaryExpr*>(e);
      // Left-deep chains are walked in a loop (the parser allows 2048 operators).
      while (b) {
        if (b->op == ast::BinaryOp::Comma && !comma_constant) return b;
        if (const ast::Expr* r = non_constant_part(b->rhs)) return r;
        const ast::Expr* lhs = b->lhs;
        b = ast::dyn_cast<ast::BinaryExpr>(lhs);
        if (!b) return non_constant_part(lhs);
      }
      return nullptr;
    }
    case ast::NodeKind::TernaryExpr: {
      const auto* t = static_cast<const ast::TernaryExpr*>(e);
      for (const ast::Expr* part : {t->condition, t->then_expr, t->else_expr})
        if (const ast::Expr* r = non_constant_part(part)) return r;
      return nullptr;
    }
    case ast::NodeKind::CallExpr: {
      const auto* c = static_cast<const ast::CallExpr*>(e);
      if (c->callee_expr) return e;
      if (!c->constructor_type && (functions_.count(c->callee) || !builtins_->is_builtin(c->callee))) {
        if (!structs_.count(c->callee)) return e;  // a user function
      }
      for (const ast::Expr* a : c->args)
        if (const ast::Expr* r = non_constant_part(a)) return r;
      return nullptr;
    }
    case ast::NodeKind::IndexExpr: {
      const auto* i = static_cast<const ast::IndexExpr*>(e);
      if (const ast::Expr* r = non_constant_part(i->base)) return r;
      return non_constant_part(i->index);
    }
    case ast::NodeKind::MemberExpr: return non_constant_part(static_cast<const ast::MemberExpr*>(e)->base);
    case ast::NodeKind::MethodCallExpr: return nullptr;  // .length() of a sized array
    case ast::NodeKind::InitializerList:
      for (const ast::Expr* x : static_cast<const ast::InitializerList*>(e)->elements)
        if (const ast::Expr* r = non_constant_part(x)) return r;
      return nullptr;
    default: return e;
  }
}

bool Checker::compatibility_profile() const {
  const LanguageLevel* level = language();
  if (!level) return true;
  return !level->es && (level->version < 140 || level->compatibility || level->extension_enabled("GL_ARB_compatibility"));
}

bool Checker::allows(const VersionGate& gate) const { return !language() || gate_allows(gate, *language()); }

void Checker::reject(SourceRange where, std::string message, const char* code, std::string hint) {
  Diagnostic d = Diagnostic::error(where, std::move(message)).with_code(code);
  if (!hint.empty()) d.with_hint(std::move(hint));
  report(std::move(d));
}

}  // namespace safegi::detail
