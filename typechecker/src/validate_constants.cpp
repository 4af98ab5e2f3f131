// Where GLSL needs a constant expression (GLSL 4.60 §4.3.3): array sizes,
// the initializers of const variables, case labels.

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

// GLSL 4.20 lets a local const take any initializer (it is then read-only, not a constant expression).
const VersionGate kNonConstantLocalConst{420, 0, {"GL_ARB_shading_language_420pack"}};

std::string spelled(const ast::Expr* e) {
  if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e)) return "'" + id->name + "'";
  if (const auto* call = ast::dyn_cast<ast::CallExpr>(e); call && !call->callee.empty()) return "the call of '" + call->callee + "'";
  if (ast::isa<ast::AssignExpr>(e)) return "an assignment";
  if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(e); b && b->op == ast::BinaryOp::Comma) return "the comma operator";
  if (ast::isa<ast::UnaryExpr>(e)) return "an increment or decrement";
  return "this";
}

}  // namespace

void Checker::validate_array_size(const ast::ArrayDim& dim, const Value& size) {
  if (size.type.is_error()) return;
  if (!(size.type.shape == Shape::scalar && size.type.is_integer() && !size.type.is_array())) {
    reject(dim.size->range, "an array size must be a constant integer expression, not " + glsl_name(size.type), code::E_ARRAY_SIZE);
    return;
  }
  if (const ast::Expr* part = non_constant_part(dim.size)) {
    report(Diagnostic::error(dim.size->range, "an array size must be a constant integer expression; " + spelled(part) +
                                                  " is not constant")
               .with_code(code::E_ARRAY_SIZE)
               .with_highlight(part->range));
  }
}

void Checker::validate_const_initializer(const ast::Declarator& decl, bool global) {
  if (!global && allows(kNonConstantLocalConst)) return;
  const ast::Expr* part = non_constant_part(decl.initializer);
  if (!part) return;
  Diagnostic d = Diagnostic::error(decl.initializer->range, "the initializer of const '" + decl.name +
                                                                "' must be a constant expression; " + spelled(part) +
                                                                " is not constant")
                     .with_code(code::E_CONST_INIT)
                     .with_highlight(part->range);
  if (!global) d.with_hint("from #version 420 (or GL_ARB_shading_language_420pack) a local const may take any value");
  report(std::move(d));
}

// GLSL ES (1.00 §4.3, 3.00 §4.3): a global's initializer is a constant
// expression, unless GL_EXT_shader_non_constant_global_initializers.
void Checker::validate_global_initializer(const ast::Declarator& decl) {
  const LanguageLevel* level = language();
  if (!level || !level->es || level->extension_enabled("GL_EXT_shader_non_constant_global_initializers")) return;
  const ast::Expr* part = non_constant_part(decl.initializer);
  if (!part) return;
  report(Diagnostic::error(decl.initializer->range, "in GLSL ES the initializer of global '" + decl.name +
                                                        "' must be a constant expression; " + spelled(part) + " is not constant")
             .with_code(code::E_CONST_INIT)
             .with_highlight(part->range)
             .with_hint("assign it in main(), or enable GL_EXT_shader_non_constant_global_initializers"));
}

}  // namespace safegi::detail
