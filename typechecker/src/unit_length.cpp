// Unit length (docs/language.md, "What spaces do not reach"). A fragment shader's
// `in normal<S>` is interpolated across the primitive, so it is shorter than 1 until
// normalize(); where its length matters (a cosine, a reflection, an offset along it, a
// declared normal or direction) the checker says so. And a unit direction's z in a
// normal-aligned frame is its cosine.

#include <algorithm>

#include <safegi/parser/printer.hpp>
#include <safegi/parser/walk.hpp>

#include "checker_impl.hpp"

namespace safegi::detail {

// `q`: the declaration's qualifiers (a block's, for its members); `flat`: the member says flat itself.
void Checker::mark_stage_normal(Type& t, const ast::TypeQualifiers& q, bool flat) const {
  const bool input = q.has("in") || q.has("attribute") || (q.has("varying") && options_.stage != Stage::vertex);
  if (!input || t.is_array() || t.geometry != Geometry::normal) return;
  // A stage's own normal (a vertex's attribute, a fragment's interpolated one) is the shaded point's:
  // it points away from it (docs/language.md, "Orientation").
  if (options_.stage == Stage::vertex || options_.stage == Stage::fragment) t.orientation = Orientation::away;
  if (options_.stage == Stage::fragment && !flat && !q.has("flat")) t.length_loss = Type::LengthLoss::interpolated;
}

// "'vN', a normal interpolated across the primitive", "'n', a normal carried by a normal matrix that may scale".
std::string Checker::not_unit_subject(const Value& v) const {
  const std::string name = written_name(v);
  return "'" + name + "', a " + geometry_name(v.type.geometry) +
         (v.type.length_loss == Type::LengthLoss::scaled     ? " carried by a normal matrix that may scale"
          : v.type.length_loss == Type::LengthLoss::filtered ? " filtered by a texture lookup"
          : v.type.length_loss == Type::LengthLoss::offset   ? " offset by an unannotated vector"
          : v.type.length_loss == Type::LengthLoss::blended  ? " summed from normals"
                                                             : " interpolated across the primitive");
}

// The value as written (`vs.n`, not the block `vs`), where it is one short line.
std::string Checker::written_name(const Value& v) const {
  Value unnamed = v;
  unnamed.name.clear();
  return operand_text(unnamed, v.name.empty() ? "n" : v.name);
}

void Checker::report_not_unit(const Value& v, const std::string& where) {
  const std::string name = written_name(v);
  Diagnostic d = Diagnostic::error(v.range, where + " " + not_unit_subject(v) + ": it is not of unit length until normalize()")
                     .with_code(code::E_KIND_MISMATCH);
  add_origin_note(d, v);
  d.with_hint("normalize it first: normalize(" + name + ")");
  report(std::move(d));
}

bool Checker::unit_length_arguments(const std::string& name, const std::vector<Value>& args) {
  if (!builtin_argument_rule(name, ArgumentRule::unit_length)) return true;
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i].type.length_loss != Type::LengthLoss::none) {
      report_not_unit(args[i], "argument " + std::to_string(i + 1) + " of '" + name + "' is");
      return false;
    }
  return true;
}

namespace {

// The body reads the parameter only as normalize(param): the function makes it unit itself
// (`vec3 n = normalize(vnormal);`), so an argument that is not of unit length is fine.
bool normalized_on_every_use(const ast::FunctionDecl* f, std::size_t param) {
  if (f == nullptr || f->body == nullptr || param >= f->params.size() || f->params[param]->name.empty()) return false;
  const std::string& name = f->params[param]->name;
  int uses = 0, normalized = 0;
  ast::walk(f->body, [&](const ast::Node& node) {
    if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(&node); id && id->name == name) ++uses;
    if (const auto* call = ast::dyn_cast<ast::CallExpr>(&node); call && call->callee == "normalize" && call->args.size() == 1)
      if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(ast::without_parens(call->args[0])); id && id->name == name)
        ++normalized;
  });
  return uses > 0 && uses == normalized;
}

}  // namespace

// A user function's normal or direction parameter takes a unit vector, unless its body
// normalizes the parameter wherever it reads it.
bool Checker::unit_length_parameters(const std::string& callee, const Function& f, const std::vector<Value>& args) {
  const std::vector<Type>& params = f.params;
  for (std::size_t i = 0; i < args.size() && i < params.size(); ++i) {
    const Geometry want = params[i].geometry;
    if (args[i].type.length_loss != Type::LengthLoss::none && (want == Geometry::normal || want == Geometry::direction) &&
        !normalized_on_every_use(f.decl, i)) {
      report_not_unit(args[i], "argument " + std::to_string(i + 1) + " of '" + callee + "' is");
      return false;
    }
  }
  return true;
}

// n * bias moves a point by bias only along a unit n.
bool Checker::unit_length_offset(ast::BinaryOp op, const Value& lhs, const Value& rhs) {
  if (op != ast::BinaryOp::Mul) return true;
  const auto lost = [](const Value& v) { return v.type.length_loss != Type::LengthLoss::none; };
  const Value* n = lost(lhs) ? &lhs : lost(rhs) ? &rhs : nullptr;
  if (n == nullptr) return true;
  const Type& scale = (n == &lhs ? rhs : lhs).type;
  const DimSlot d = value_dimension(scale, result_.registry);
  if (scale.shape != Shape::scalar || !d.is_known() || d.value.is_dimensionless()) return true;
  report_not_unit(*n, "an offset of " + name_of(scale) + " along");
  return false;
}

// In a frame whose z axis is the surface normal (`space shading : frame;`, pbrt's shading space)
// a unit direction's z is its cosine to the normal: CosTheta(w) = w.z.
std::optional<Dimension> Checker::frame_cosine(const Type& t) const {
  const bool unit = t.geometry == Geometry::direction || t.geometry == Geometry::normal;
  if (!unit || t.length_loss != Type::LengthLoss::none || !t.from.is_known() || !result_.registry.is_frame_space(t.from.id)) return std::nullopt;
  return result_.registry.find_dimension("proj");
}

namespace {

using ast::without_parens;

// The variable an assignment, ++/-- or out argument writes: `L` of `L`, `L.x`, `L[i]`.
const ast::IdentifierExpr* written_variable(const ast::Expr* e) {
  for (e = without_parens(e); e != nullptr; e = without_parens(e)) {
    if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e)) return id;
    if (const auto* m = ast::dyn_cast<ast::MemberExpr>(e)) e = m->base;
    else if (const auto* i = ast::dyn_cast<ast::IndexExpr>(e)) e = i->base;
    else return nullptr;
  }
  return nullptr;
}

}  // namespace

// Only a local, a parameter or a read-only global: any call may write another global.
std::optional<LengthOf> Checker::length_of_variable(const ast::Expr* arg) {
  const auto* id = ast::dyn_cast<ast::IdentifierExpr>(without_parens(arg));
  const Variable* var = id ? lookup(id->name) : nullptr;
  if (var == nullptr || var->builtin || !var->range.valid()) return std::nullopt;
  const bool global = scopes_.front().contains(id->name) && &scopes_.front().at(id->name) == var;
  if (global && !var->read_only) return std::nullopt;
  return LengthOf{id->name, var->range, var->version};
}

std::optional<Value> Checker::divided_by_own_length(const ast::Expr* numerator, const Value& lhs, const Value& rhs,
                                                    SourceRange range) {
  const auto* id = numerator ? ast::dyn_cast<ast::IdentifierExpr>(without_parens(numerator)) : nullptr;
  if (id == nullptr || !rhs.length_of || rhs.length_of->name != id->name) return std::nullopt;
  const Variable* var = lookup(id->name);
  if (var == nullptr || var->range != rhs.length_of->declared_at || var->version != rhs.length_of->version) return std::nullopt;
  if (lhs.type.shape != Shape::vector || !lhs.type.is_floating()) return std::nullopt;
  std::vector<Value> args{lhs};
  Value unit = builtin_call(nullptr, "normalize", *builtins_->find("normalize"), args, range, range);
  if (unit.type.is_error()) return std::nullopt;
  unit.range = range;
  return unit;
}

// Orthonormal frames. A basis built around a normal, t = normalize(cross(up, n)) or Gram-Schmidt's
// t = normalize(x - n * dot(x, n)), then b = cross(n, t), has a unit b: the cross product of two
// unit vectors has unit length exactly when they are perpendicular, which these constructions make
// them. Without this, mat3(t, b, n) would be a linear frame and a rigid one refused.
void Checker::carry_perpendicular(const ast::CallExpr& e, const std::vector<Value>& args, Value& v) {
  if (e.callee == "normalize" && args.size() == 1) {
    v.perpendicular_to = args[0].perpendicular_to;
    // The unit cross product of two vectors of a surface (edges, derivatives of a point) is its normal.
    if (args[0].plane_normal && v.type.geometry == Geometry::direction) {
      v.type.geometry = Geometry::normal;
      v.type.orientation = Orientation::none;
    }
    return;
  }
  if (e.callee != "cross" || args.size() != 2) return;
  const std::optional<VariableAt> a = length_of_variable(e.args[0]), b = length_of_variable(e.args[1]);
  const auto knows = [](const Value& x, const std::optional<VariableAt>& y) {
    return y && std::find(x.perpendicular_to.begin(), x.perpendicular_to.end(), *y) != x.perpendicular_to.end();
  };
  const auto unit = [](const Value& x) {
    return (x.type.geometry == Geometry::direction || x.type.geometry == Geometry::normal) &&
           x.type.length_loss == Type::LengthLoss::none;
  };
  if (v.type.geometry == Geometry::vector && unit(args[0]) && unit(args[1]) && (knows(args[0], b) || knows(args[1], a))) {
    v.type.geometry = Geometry::direction;
    v.type.orientation = Orientation::none;
  }
  v.plane_normal = args[0].type.geometry == Geometry::vector && args[1].type.geometry == Geometry::vector &&
                   v.type.geometry == Geometry::vector;
  v.perpendicular_to.clear();
  for (const std::optional<VariableAt>& x : {a, b})
    if (x) v.perpendicular_to.push_back(*x);
}

// `x - n * dot(x, n)` (either factor order, dot's arguments either way) of a unit n is x without
// its component along n: perpendicular to n.
void Checker::gram_schmidt(const ast::BinaryExpr& e, Value& v) {
  const auto* product = ast::dyn_cast<ast::BinaryExpr>(without_parens(e.rhs));
  if (product == nullptr || product->op != ast::BinaryOp::Mul || e.lhs == nullptr) return;
  for (auto [along, projection] : {std::pair{product->lhs, product->rhs}, std::pair{product->rhs, product->lhs}}) {
    const auto* dot = ast::dyn_cast<ast::CallExpr>(without_parens(projection));
    const auto* n = ast::dyn_cast<ast::IdentifierExpr>(without_parens(along));
    if (dot == nullptr || n == nullptr || dot->callee != "dot" || dot->args.size() != 2) continue;
    const std::string x = print_expression(*without_parens(e.lhs));  // printed only for a candidate
    const std::string first = print_expression(*without_parens(dot->args[0]));
    const std::string second = print_expression(*without_parens(dot->args[1]));
    if (!((first == x && second == n->name) || (second == x && first == n->name))) continue;
    const Variable* var = lookup(n->name);
    if (var == nullptr || (var->type.geometry != Geometry::direction && var->type.geometry != Geometry::normal)) continue;
    if (std::optional<VariableAt> at = length_of_variable(along)) v.perpendicular_to = {*at};
    return;
  }
}

void Checker::note_write(const ast::Expr* target) {
  const ast::IdentifierExpr* id = written_variable(target);
  if (id == nullptr) return;
  for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
    if (auto found = scope->find(id->name); found != scope->end()) {
      ++found->second.version;
      found->second.length_of.reset();
      found->second.perpendicular_to.clear();
      found->second.unit_sign = false;
      found->second.plane_normal = false;
      found->second.dot_of.reset();
      found->second.inverse_squares = 0;
      found->second.pi_constant.reset();
      return;
    }
}

void Checker::note_writes(const ast::Node* n) {
  ast::walk(n, [this](const ast::Node& node) {
    if (const auto* a = ast::dyn_cast<ast::AssignExpr>(&node)) {
      note_write(a->lhs);
    } else if (const auto* u = ast::dyn_cast<ast::UnaryExpr>(&node)) {
      if (u->op == ast::UnaryOp::PreInc || u->op == ast::UnaryOp::PreDec || u->op == ast::UnaryOp::PostInc ||
          u->op == ast::UnaryOp::PostDec)
        note_write(u->operand);
    } else if (const auto* c = ast::dyn_cast<ast::CallExpr>(&node); c && !c->constructor_type) {
      // A builtin without out parameters writes nothing; a function of the program may write any argument.
      const std::vector<Signature>* sigs = functions_.contains(c->callee) ? nullptr : builtins_->find(c->callee);
      const bool writes = sigs == nullptr || std::any_of(sigs->begin(), sigs->end(), [](const Signature& s) {
                            return std::any_of(s.params.begin(), s.params.end(), [](const auto& p) { return p.is_out; });
                          });
      if (writes)
        for (const ast::Expr* arg : c->args) note_write(arg);
    }
  });
}

}  // namespace safegi::detail
