// Subroutines (GLSL 4.00 §6.1.2, GL_ARB_shader_subroutine): a subroutine
// type is a function prototype qualified `subroutine`; `subroutine
// (T1, T2) f` implements types; a `subroutine uniform T u` (or an array of
// them) is called like a function of type T.

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

bool same_signature(const Function& a, const Function& b) {
  if (a.params.size() != b.params.size() || !same_glsl_type(a.result, b.result)) return false;
  for (std::size_t i = 0; i < a.params.size(); ++i)
    if (!same_glsl_type(a.params[i], b.params[i]) || a.out_params[i] != b.out_params[i] ||
        a.inout_params[i] != b.inout_params[i])
      return false;
  return true;
}

constexpr const char* kSubroutinePrefix = "subroutine ";

}  // namespace

// Returns true when `d` declares a subroutine type (it is then no callable function).
bool Checker::subroutine_declaration(const ast::FunctionDecl& d, const Function& f) {
  const ast::Qualifier* subroutine = nullptr;
  for (const ast::Qualifier& q : d.qualifiers.list) {
    if (q.kind != ast::QualifierKind::Subroutine) continue;
    if (subroutine) {
      reject(q.range, "a function takes one 'subroutine' qualifier", code::E_SUBROUTINE);
      return false;
    }
    subroutine = &q;
  }
  if (!subroutine) return false;
  if (!subroutine->has_type_list) {
    subroutine_types_[d.name] = f;
    return true;
  }
  if (subroutine->type_names.empty()) {
    reject(subroutine->range, "'subroutine (...)' names at least one subroutine type", code::E_SUBROUTINE);
    return false;
  }
  if (!d.body) {
    reject(d.name_range, "a function implementing a subroutine type must be defined here, not only declared",
           code::E_SUBROUTINE);
    return false;
  }
  for (const std::string& type : subroutine->type_names) {
    auto it = subroutine_types_.find(type);
    if (it == subroutine_types_.end()) {
      reject(subroutine->range, "'" + type + "' is not a subroutine type", code::E_SUBROUTINE,
             "declare it first: 'subroutine <return type> " + type + "(<parameters>);'");
      return false;
    }
    if (!same_signature(it->second, f)) {
      report(Diagnostic::error(d.name_range, "'" + d.name + "' does not match subroutine type '" + type +
                                                 "': the return type and every parameter must be the same")
                 .with_code(code::E_SUBROUTINE)
                 .with_note(Diagnostic::note(it->second.decl->name_range, "'" + type + "' is declared here")));
      return false;
    }
  }
  return false;
}

std::optional<Type> Checker::subroutine_type(const std::string& name) const {
  if (!subroutine_types_.count(name)) return std::nullopt;
  Type t;
  t.shape = Shape::opaque;
  t.opaque = kSubroutinePrefix + name;
  return t;
}

std::optional<Value> Checker::subroutine_call(const ast::CallExpr& e, std::vector<Value>& args) {
  Type callee;
  if (e.callee_expr) {
    callee = expr(e.callee_expr).type;
  } else if (const Variable* v = lookup(e.callee)) {
    callee = v->type;
  } else {
    return std::nullopt;
  }
  if (callee.shape != Shape::opaque || callee.opaque.rfind(kSubroutinePrefix, 0) != 0) {
    if (!e.callee_expr) return std::nullopt;
    if (!callee.is_error()) reject(e.callee_expr->range, "called object is not a subroutine uniform", code::E_UNDECLARED_FUNCTION);
    return error_value(e.range);
  }
  if (callee.is_array()) {
    reject(e.callee_expr ? e.callee_expr->range : e.callee_range, "index the subroutine uniform array to call one element",
           code::E_SUBROUTINE);
    return error_value(e.range);
  }
  for (const Value& a : args)
    if (a.type.is_error()) return error_value(e.range);
  const Function& type = subroutine_types_.at(callee.opaque.substr(std::string(kSubroutinePrefix).size()));
  return user_call(e, std::vector<Function>{type}, args);
}

}  // namespace safegi::detail
