// Writes GLSL forbids although the target is a variable: whole arrays
// before GLSL 1.20 / in ESSL 1.00, readonly members of named buffer blocks,
// and a tessellation control shader's per-vertex outputs at another vertex
// than its own (GLSL 4.60 §4.3.6, ARB_tessellation_shader).

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

const VersionGate kArrayAssignment{120, 300};

// The variable an l-value expression writes, through members, swizzles and
// indices; `first_index` gets the index applied directly to it.
const ast::IdentifierExpr* written_variable(const ast::Expr* e, const ast::IndexExpr** first_index,
                                            const ast::MemberExpr** first_member) {
  *first_index = nullptr;
  *first_member = nullptr;
  while (e) {
    if (const auto* p = ast::dyn_cast<ast::ParenExpr>(e)) {
      e = p->inner;
    } else if (const auto* m = ast::dyn_cast<ast::MemberExpr>(e)) {
      *first_member = m;
      e = m->base;
    } else if (const auto* i = ast::dyn_cast<ast::IndexExpr>(e)) {
      *first_index = i;
      e = i->base;
    } else {
      break;
    }
  }
  return ast::dyn_cast<ast::IdentifierExpr>(e);
}

}  // namespace

bool Checker::validate_assignment(const ast::Expr* target, const Value& value) {
  if (value.type.is_array() && !allows(kArrayAssignment)) {
    reject(target->range, "an array cannot be assigned as a whole in " + std::string(language()->es ? "GLSL ES 1.00" : "GLSL 1.10"),
           code::E_NOT_ASSIGNABLE, "assign its elements one by one");
    return false;
  }
  const ast::IndexExpr* index = nullptr;
  const ast::MemberExpr* member = nullptr;
  const ast::IdentifierExpr* root = written_variable(target, &index, &member);
  if (!root) return true;
  // `buf.member` where the member of a named buffer block is readonly.
  if (member && ast::isa<ast::IdentifierExpr>(member->base)) {
    auto it = validation_.readonly_members.find(root->name + "." + member->member);
    if (it != validation_.readonly_members.end()) {
      report(Diagnostic::error(target->range, "cannot assign to readonly member '" + member->member + "'")
                 .with_code(code::E_NOT_ASSIGNABLE)
                 .with_note(Diagnostic::note(it->second, "'" + member->member + "' is declared readonly here")));
      return false;
    }
  }
  // A tessellation control shader writes only its own vertex: out[gl_InvocationID].
  if (options_.stage != Stage::tess_control) return true;
  const Variable* v = lookup(root->name);
  // By declaration, not by name: a local of the same name shadows the output.
  const auto output = validation_.per_vertex_outputs.find(root->name);
  const bool per_vertex_output = root->name == "gl_out" || (v && !v->builtin && output != validation_.per_vertex_outputs.end() &&
                                                            v->range == output->second);
  if (!per_vertex_output) return true;
  const auto* invocation = index && index->base == root ? ast::dyn_cast<ast::IdentifierExpr>(index->index) : nullptr;
  if (invocation && invocation->name == "gl_InvocationID") return true;
  reject(index && index->base == root ? index->index->range : root->range,
         "a tessellation control shader writes its per-vertex output '" + root->name + "' only at [gl_InvocationID]",
         code::E_NOT_ASSIGNABLE, "other vertices' outputs are read-only here; index with gl_InvocationID");
  return false;
}

}  // namespace safegi::detail
