// Statement rules beyond types: the shape of a switch body and its case
// labels (GLSL 4.60 §6.2; GLSL 1.30 and ESSL 3.00 say the same); compute
// shaders before 4.30.

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

// int case labels of a uint switch (and back) convert implicitly from GLSL 4.00 on.
const VersionGate kImplicitIntToUint{400, 0, {"GL_ARB_gpu_shader5", "GL_MESA_shader_integer_functions"}};

bool is_label(const ast::Stmt* s) {
  return s && (s->kind == ast::NodeKind::CaseLabel || s->kind == ast::NodeKind::DefaultLabel);
}

const VersionGate kComputeShaders{430, 310, {"GL_ARB_compute_shader"}};

}  // namespace

// Compute shaders before GLSL 4.30 / ESSL 3.10 need GL_ARB_compute_shader.
// Vulkan GLSL sets the block defaults.
// Geometry and tessellation shaders are not gated by #version: piglit expects
// a geometry shader without #version (glsl-1.50/compiler/uniforms.geom) and
// tessellation shaders at #version 110 (nv_viewport_array2) to compile.
void Checker::validate_stage(const ast::TranslationUnit& unit) {
  // GL_KHR_vulkan_glsl: uniform blocks are std140 and buffer blocks std430 by default.
  if (vulkan_glsl(language())) {
    validation_.uniform_packing = "std140";
    validation_.buffer_packing = "std430";
  }
  SourceRange where = options_.version_range;
  if (!where.valid()) where = unit.decls.empty() ? unit.range : SourceRange{unit.decls.front()->range.begin, unit.decls.front()->range.begin};
  const VersionGate* gate = options_.stage == Stage::compute ? &kComputeShaders : nullptr;
  if (!gate || allows(*gate)) return;
  const LanguageLevel& level = *language();
  reject(where, std::string(stage_name(options_.stage)) + " shaders require " +
                                         gate_requirement(*gate, level.es) + "; the shader is #version " +
                                         std::to_string(level.version) + (level.es ? " es" : ""),
         code::E_VERSION);
}

Checker::FlowScope::FlowScope(Checker& c, const ast::Stmt* s) : checker(c) {
  const ast::NodeKind k = s->kind;
  counted = k == ast::NodeKind::IfStmt || k == ast::NodeKind::WhileStmt || k == ast::NodeKind::DoStmt ||
            k == ast::NodeKind::ForStmt || k == ast::NodeKind::SwitchStmt;
  c.validation_.flow_depth += counted;
  if (k == ast::NodeKind::ReturnStmt && c.current_function_) c.validation_.returned_from = c.current_function_;
}

// GLSL 4.60 §8.16 (barrier() in a tessellation control shader) and
// GL_ARB_fragment_shader_interlock: only in main(), outside any control flow,
// before any return; each interlock call once, begin before end.
void Checker::validate_call_placement(const ast::CallExpr& e) {
  const std::string& name = e.callee;
  const bool interlock = name == "beginInvocationInterlockARB" || name == "endInvocationInterlockARB";
  const bool tess_barrier = name == "barrier" && options_.stage == Stage::tess_control && !functions_.count(name);
  if (!interlock && !tess_barrier) return;
  const bool in_main = current_function_ && current_function_->name == "main";
  std::string problem;
  if (!in_main) problem = "only in main()";
  else if (validation_.flow_depth > 0) problem = "only outside control flow (if, loops, switch)";
  else if (validation_.returned_from == current_function_) problem = "only before a return from main()";
  if (!problem.empty()) {
    reject(e.callee_range, "'" + name + "()' may be called " + problem, code::E_CALL_PLACEMENT,
           tess_barrier ? "every invocation of the patch must reach the barrier" : "");
    return;
  }
  if (!interlock) return;
  if (auto it = validation_.called_once.find(name); it != validation_.called_once.end()) {
    report(Diagnostic::error(e.callee_range, "'" + name + "()' may be called only once")
               .with_code(code::E_CALL_PLACEMENT)
               .with_note(Diagnostic::note(it->second, "the first call is here")));
    return;
  }
  if (name == "endInvocationInterlockARB" && !validation_.called_once.count("beginInvocationInterlockARB")) {
    reject(e.callee_range, "'endInvocationInterlockARB()' must follow beginInvocationInterlockARB()", code::E_CALL_PLACEMENT);
    return;
  }
  validation_.called_once.emplace(name, e.callee_range);
}

void Checker::validate_switch(const ast::SwitchStmt& s, const Type& selector) {
  switches_.push_back({selector, {}});
  if (!s.body || s.body->statements.empty()) return;
  const std::vector<ast::Stmt*>& body = s.body->statements;
  if (!is_label(body.front())) {
    reject(body.front()->range, "a switch body must begin with a 'case' or 'default' label", code::E_SWITCH,
           "statements before the first label could never run");
    return;
  }
  if (is_label(body.back())) {
    reject(body.back()->range, "the last label of a switch must be followed by a statement", code::E_SWITCH,
           "add 'break;' after it");
    return;
  }
  const ast::Stmt* first_default = nullptr;
  for (const ast::Stmt* st : body) {
    if (!st || st->kind != ast::NodeKind::DefaultLabel) continue;
    if (first_default) {
      report(Diagnostic::error(st->range, "a switch has at most one 'default' label")
                 .with_code(code::E_SWITCH)
                 .with_note(Diagnostic::note(first_default->range, "the first 'default' is here")));
      return;
    }
    first_default = st;
  }
}

void Checker::validate_case(const ast::CaseLabel& label, const Value& value) {
  if (switches_.empty() || value.type.is_error()) return;
  SwitchContext& sw = switches_.back();
  const SourceRange where = label.value->range;
  if (!(value.type.shape == Shape::scalar && value.type.is_integer() && !value.type.is_array())) {
    reject(where, "a case label must be a constant integer expression, not " + glsl_name(value.type), code::E_SWITCH);
    return;
  }
  if (const ast::Expr* part = non_constant_part(label.value)) {
    report(Diagnostic::error(where, "a case label must be a constant integer expression")
               .with_code(code::E_SWITCH)
               .with_highlight(part->range));
    return;
  }
  if (!value.constant) return;  // constant, but not folded here
  if (!sw.selector.is_error() && sw.selector.shape == Shape::scalar && sw.selector.is_integer() &&
      sw.selector.scalar != value.type.scalar && !allows(kImplicitIntToUint)) {
    reject(where, "case label of type " + glsl_name(value.type) + " in a switch on " + glsl_name(sw.selector) +
                      "; before #version 400 the types must be the same",
           code::E_SWITCH, value.type.scalar == Scalar::int_ ? "write the label as " + std::to_string(*value.constant) + "u" : "");
    return;
  }
  for (const auto& [seen, range] : sw.cases) {
    if (seen != *value.constant) continue;
    report(Diagnostic::error(where, "duplicate case value " + std::to_string(*value.constant))
               .with_code(code::E_SWITCH)
               .with_note(Diagnostic::note(range, "the same value is here")));
    return;
  }
  sw.cases.emplace_back(*value.constant, where);
}

}  // namespace safegi::detail
