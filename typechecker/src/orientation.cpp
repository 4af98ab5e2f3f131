// Orientation of vectors and directions relative to the shaded point
// (docs/language.md, "Orientation"; issue #21, item 4). A difference of the
// shaded point and another point is oriented; negation, sums and built-ins
// carry or check the orientation; a stored, passed or returned value whose
// orientation clashes with the declared one is E-ORIENTATION.

#include <algorithm>
#include <cctype>
#include <safegi/parser/printer.hpp>

#include "checker_impl.hpp"

namespace safegi::detail {
namespace {

using ast::without_parens;

// `x` as an operand of unary minus: names, members, indices and calls need no parentheses.
std::string negated(const ast::Expr* e) {
  const bool simple = ast::isa<ast::IdentifierExpr>(e) || ast::isa<ast::MemberExpr>(e) || ast::isa<ast::IndexExpr>(e) ||
                      ast::isa<ast::CallExpr>(e);
  return simple ? "-" + print_expression(*e) : "-(" + print_expression(*e) + ")";
}

}  // namespace

Orientation point_difference_orientation(const Type& a, const Type& b) {
  if (a.geometry != Geometry::point || b.geometry != Geometry::point) return Orientation::none;
  const bool a_shaded = a.orientation == Orientation::shaded, b_shaded = b.orientation == Orientation::shaded;
  if (a_shaded == b_shaded) return Orientation::none;  // neither (or both) is the shaded point
  return b_shaded ? Orientation::away : Orientation::toward;
}

Orientation sum_orientation(bool add, Orientation a, Orientation b) {
  if (a == Orientation::none || a == Orientation::shaded) return Orientation::none;
  return (add ? b == a : b == flipped(a)) ? a : Orientation::none;
}

Orientation scaled_orientation(Orientation o, const Value& scale) {
  if (!scale.number) return o;  // a length, a cosine, a weight: taken as positive
  if (*scale.number == 0.0) return Orientation::none;
  return *scale.number < 0.0 ? flipped(o) : o;
}

const ast::Expr* Checker::expression_at(SourceRange range) const {
  if (!range.valid()) return nullptr;
  const ast::Expr* found = nullptr;
  for (const auto& [node, type] : result_.types)
    if (node->range == range && dynamic_cast<const ast::Expr*>(node)) {
      found = static_cast<const ast::Expr*>(node);
      if (!ast::isa<ast::ParenExpr>(node)) break;
    }
  return found;
}

std::string Checker::reversed_expression(const ast::Expr* e) const {
  e = without_parens(e);
  if (const auto* u = ast::dyn_cast<ast::UnaryExpr>(e); u && u->op == ast::UnaryOp::Minus) {
    // -p of a point is origin - p; the other way is p measured from the origin, vector<S>(p).
    const auto operand = result_.types.find(u->operand);
    if (operand != result_.types.end() && operand->second.geometry == Geometry::point)
      return "vector<" + name_of_space(operand->second.from) + ">(" + print_expression(*u->operand) + ")";
    return print_expression(*u->operand);
  }
  if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(e); b && b->op == ast::BinaryOp::Sub) {
    const auto lhs = result_.types.find(b->lhs), rhs = result_.types.find(b->rhs);
    if (lhs != result_.types.end() && rhs != result_.types.end() &&
        point_difference_orientation(lhs->second, rhs->second) != Orientation::none)
      return print_expression(*b->rhs) + " - " + print_expression(*b->lhs);
  }
  if (const auto* call = ast::dyn_cast<ast::CallExpr>(e)) {
    if (call->callee == "normalize" && call->args.size() == 1) return "normalize(" + reversed_expression(call->args[0]) + ")";
  }
  return negated(e);
}

std::string Checker::orientation_hint(const Value& value, Orientation expected) const {
  const ast::Expr* e = expression_at(value.range);
  if (!e) return {};
  const ast::Expr* inner = without_parens(e);
  if (const auto* call = ast::dyn_cast<ast::CallExpr>(inner)) {
    if (call->callee == "normalize" && call->args.size() == 1) inner = without_parens(call->args[0]);
  }
  const std::string fix = reversed_expression(e);
  const std::string way = expected == Orientation::away ? "away from" : "toward";
  if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(inner); b && b->op == ast::BinaryOp::Sub && fix.find(" - ") != std::string::npos) {
    const auto lhs = result_.types.find(b->lhs);
    const bool lhs_shaded = lhs != result_.types.end() && lhs->second.orientation == Orientation::shaded;
    const std::string shaded = print_expression(lhs_shaded ? *b->lhs : *b->rhs);
    return "q - p points from p to q: this one points " + std::string(lhs_shaded ? "toward" : "away from") +
           " the shaded point " + shaded + "; the one " + way + " it is " + fix;
  }
  return "negate it to point " + way + " the shaded point: " + fix;
}

std::optional<Orientation> Checker::builtin_orientation(const std::string& name, const std::vector<Value>& args,
                                                        SourceRange call_range) {
  // The built-ins that read an orientation: GLSL's incident vector I points toward the surface.
  struct Incident {
    const char* name;
    std::size_t param;
  };
  static const Incident kIncident[] = {{"reflect", 0}, {"refract", 0}, {"faceforward", 1}};
  for (const Incident& rule : kIncident) {
    if (name != rule.name || args.size() <= rule.param) continue;
    const Value& incident = args[rule.param];
    if (incident.type.orientation == Orientation::away) {
      Diagnostic d = Diagnostic::error(incident.range, "argument " + std::to_string(rule.param + 1) + " of '" + name + "' has type " +
                                                           name_of(incident.type) + ", but '" + name +
                                                           "' takes the incident direction, which points toward the surface")
                         .with_code(code::E_ORIENTATION)
                         .with_highlight(call_range);
      add_origin_note(d, incident);
      // The call again with the incident direction reversed, when every argument has its expression.
      std::string fixed = name + "(";
      for (std::size_t i = 0; i < args.size() && !fixed.empty(); ++i) {
        const ast::Expr* e = expression_at(args[i].range);
        if (!e) fixed.clear();
        else fixed += (i ? ", " : "") + (i == rule.param ? reversed_expression(e) : print_expression(*e));
      }
      d.with_hint(std::string(name == "faceforward" ? "faceforward(N, I, Nref)" : name + "(I, N)") +
                  " takes I toward the surface" + (fixed.empty() ? std::string() : ": " + fixed + ")"));
      report(std::move(d));
      return std::nullopt;
    }
    if (name == "faceforward") return Orientation::none;
    return incident.type.orientation == Orientation::toward ? Orientation::away : Orientation::none;
  }
  if (name == "dot" && args.size() == 2) {
    // The shaded point's normal points away from it: a cosine with a direction toward the
    // surface (a light's travel direction, an incident ray) is negative where the surface faces it.
    auto sign = [](Orientation o) { return o == Orientation::away ? 1 : o == Orientation::toward ? -1 : 0; };
    return sign(args[0].type.orientation) * sign(args[1].type.orientation) < 0 ? Orientation::toward : Orientation::none;
  }
  if ((name == "max" || name == "clamp" || name == "acos") && !negative_cosine_kept(name, args, call_range)) return std::nullopt;
  if (name == "normalize" && args.size() == 1) return args[0].type.orientation;
  if (name == "transform" && args.size() == 2) return args[1].type.orientation;  // the shaded point moves with its space
  return Orientation::none;
}

// The other argument of a dot(n, w) or dot(w, n) among the factors of `product` — the call, or a
// local it initialised (`float ndotl = dot(n, w);`) — where w is written `w_text`; empty when none.
std::string Checker::dot_partner(const ast::Expr* product, const std::string& w_text) const {
  auto partner = [&](const std::string& a, const std::string& b) { return a == w_text ? b : b == w_text ? a : std::string(); };
  std::vector<const ast::Expr*> factors{product};
  while (!factors.empty()) {
    const ast::Expr* f = without_parens(factors.back());
    factors.pop_back();
    std::string n;
    if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(f); b && b->op == ast::BinaryOp::Mul) {
      factors.push_back(b->lhs);
      factors.push_back(b->rhs);
    } else if (const auto* dot = ast::dyn_cast<ast::CallExpr>(f); dot && dot->callee == "dot" && dot->args.size() == 2) {
      n = partner(print_expression(*dot->args[0]), print_expression(*dot->args[1]));
    } else if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(f)) {
      const Variable* cosine = lookup(id->name);
      if (cosine && cosine->dot_of) n = partner(cosine->dot_of->first, cosine->dot_of->second);
    }
    if (!n.empty()) return n;
  }
  return {};
}

// The reflection written out mirrors w about n in one orientation only: 2 n (n·w) - w for a w
// that points away from the surface (pbrt's wo), and w - 2 n (n·w) — GLSL's reflect(w, n) —
// for an incident w, toward it. The other orientation comes out pointing into the surface.
bool Checker::written_reflection_ok(const Value& lhs, const Value& rhs, SourceRange op_range) {
  if (!vectorish(rhs.type.geometry) || !vectorish(lhs.type.geometry)) return true;
  const bool mirrored_away = rhs.type.orientation == Orientation::toward;  // 2 n (n·w) - w
  const bool mirrored_incident = lhs.type.orientation == Orientation::away;  // w - 2 n (n·w)
  if (!mirrored_away && !mirrored_incident) return true;
  const Value& w_value = mirrored_away ? rhs : lhs;
  const ast::Expr* product = without_parens(expression_at((mirrored_away ? lhs : rhs).range));
  const ast::Expr* w = without_parens(expression_at(w_value.range));
  if (product == nullptr || w == nullptr) return true;
  const std::string w_text = print_expression(*w);
  const std::string n_text = dot_partner(product, w_text);
  if (n_text.empty()) return true;
  const std::string message =
      mirrored_away ? "2 n (n·w) - w mirrors w about n only when w points away from the surface, and '" + w_text +
                          "' points toward it: the result points into the surface"
                    : "w - 2 n (n·w) is reflect(w, n), which mirrors an incident w (toward the surface), and '" + w_text +
                          "' points away from it: the result points into the surface";
  Diagnostic d = Diagnostic::error(w_value.range, message).with_code(code::E_ORIENTATION).with_highlight(op_range);
  add_origin_note(d, w_value);
  d.with_hint(mirrored_away ? "the reflection of an incident direction is reflect(" + w_text + ", " + n_text + ")"
                            : "the mirror image of a direction that points away is reflect(-" + w_text + ", " + n_text + ")");
  report(std::move(d));
  return false;
}

namespace {

// `lightTravel`, `incidentDir`: a name that says the direction travels toward the surface, as declared.
bool named_as_travel(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name.find("travel") != std::string::npos || name.find("incid") != std::string::npos ||
         name.find("propag") != std::string::npos;
}

}  // namespace

// max(dot(n, d), 0.0) with d toward the surface is 0 wherever the surface faces d: the sign of
// the cosine of incidence is the real bug (a light's travel direction not negated).
bool Checker::negative_cosine_kept(const std::string& name, const std::vector<Value>& args, SourceRange call_range) {
  const Value* cosine = nullptr;
  bool zero_bound = false;
  for (const Value& a : args) {
    if (a.type.shape == Shape::scalar && a.type.orientation == Orientation::toward) cosine = &a;
    zero_bound = zero_bound || (a.number && *a.number == 0.0);
  }
  const bool angle = name == "acos";  // the angle to the other side, π − θ
  if (cosine == nullptr || (!zero_bound && !angle)) return true;
  std::string fixed;  // dot(n, -d) when the argument is the dot product itself
  std::string declared;  // the annotation of a declared `toward` direction, which may be what is wrong
  if (const auto* call = ast::dyn_cast<ast::CallExpr>(without_parens(expression_at(cosine->range)));
      call && call->callee == "dot" && call->args.size() == 2) {
    for (std::size_t i = 0; i < 2; ++i) {
      const auto found = result_.types.find(call->args[i]);
      if (found != result_.types.end() && found->second.orientation == Orientation::toward && found->second.geometry != Geometry::none) {
        fixed = "dot(" + (i == 0 ? reversed_expression(call->args[0]) + ", " + print_expression(*call->args[1])
                                 : print_expression(*call->args[0]) + ", " + reversed_expression(call->args[1])) + ")";
        // A light direction declared `toward` by a reader who meant "toward the light".
        if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(without_parens(call->args[i])))
          if (const Variable* v = lookup(id->name);
              v && !v->builtin && v->read_only && !v->origin.inferred && !named_as_travel(id->name)) {
            Type away = found->second;
            away.orientation = Orientation::away;
            declared = "; or, if '" + id->name + "' points from the surface (to the light), declare it " + name_of(away) +
                       ": 'toward' means pointing at the shaded point";
          }
      }
    }
  }
  const std::string between = "a cosine between the shaded point's normal and a direction toward the surface";
  Diagnostic d = Diagnostic::error(cosine->range, angle ? "'acos' of " + between + " is the angle to the other side of the surface, π − θ"
                                                        : "'" + name + "' bounds at 0 " + between +
                                                              ": it is negative wherever the surface faces that direction, so the "
                                                              "result is 0 there")
                     .with_code(code::E_ORIENTATION)
                     .with_highlight(call_range);
  add_origin_note(d, *cosine);
  d.with_hint("the cosine of incidence takes the direction away from the surface" +
              (fixed.empty() ? std::string(": negate the direction toward it") : ": " + fixed) + declared);
  report(std::move(d));
  return false;
}

}  // namespace safegi::detail
