// Conversions, `e in target` (docs/language.md, "Conversions"): to another
// unit of the same dimension by a constant factor, or to another space through
// the shortest chain of maps in scope, which must be unique.

#include <algorithm>
#include <map>
#include <tuple>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// A map variable in scope, as an edge of the space graph.
struct MapEdge {
  const Variable* variable = nullptr;
  Geometry kind = Geometry::map;
  SpaceSlot from, to;
};

// A node of the search: a space, and whether the value is homogeneous there
// (after a projmap, only projmaps apply).
struct Node {
  SpaceSlot space;
  bool homogeneous = false;
  friend bool operator<(const Node& a, const Node& b) {
    return std::tie(a.space.state, a.space.id, a.homogeneous) < std::tie(b.space.state, b.space.id, b.homogeneous);
  }
  friend bool operator==(const Node&, const Node&) = default;
};

bool edge_applies(const MapEdge& edge, Geometry value, bool homogeneous) {
  if (edge.kind == Geometry::projmap) return value == Geometry::point || value == Geometry::hpoint;
  return !homogeneous;  // affine maps take points, vectors, directions and normals, not hpoints
}

std::string arrow(const MapEdge& e, const Checker& c) {
  return "'" + e.variable->name + "' (" + c.name_of_space(e.from) + " → " + c.name_of_space(e.to) + ")";
}

std::string chain_text(const std::vector<const MapEdge*>& chain) {
  std::string out;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) out += (out.empty() ? "" : " * ") + (*it)->variable->name;
  return out;
}

}  // namespace

Value Checker::convert(const ast::ConvertExpr& e) {
  Value v = expr(e.operand);
  if (v.type.is_error()) return error_value(e.range);
  const auto* name = ast::dyn_cast<ast::DimName>(e.target);
  if (name) {
    if (template_spaces_)
      for (std::size_t i = 0; i < template_spaces_->size(); ++i)
        if ((*template_spaces_)[i] == name->name) return convert_space(e, v, SpaceSlot::generic(static_cast<std::uint32_t>(i)));
    if (std::optional<SpaceId> s = result_.registry.find_space(name->name)) return convert_space(e, v, SpaceSlot::known(*s));
    if (!result_.registry.find_unit(name->name) && !result_.registry.find_dimension(name->name)) {
      report(Diagnostic::error(e.target->range, "unknown space or unit '" + name->name + "'")
                 .with_code(code::E_UNKNOWN_SPACE)
                 .with_hint("'in' converts to a declared space ('space " + name->name + ";') or unit ('unit " + name->name +
                            " : length = 0.3048;')"));
      return error_value(e.range);
    }
  }
  std::optional<Dimension> unit = resolve_unit(e.target);
  if (!unit) return error_value(e.range);
  return convert_unit(e, v, *unit);
}

Value Checker::convert_unit(const ast::ConvertExpr& e, const Value& v, const Dimension& target) {
  const DimensionRegistry& reg = result_.registry;
  const std::string unit_text = reg.format_units(target);
  auto fail = [&](const std::string& message, const std::string& hint, const char* code) {
    Diagnostic d = Diagnostic::error(e.range, message).with_code(code).with_highlight(e.operand->range);
    add_origin_note(d, v);
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
    return error_value(e.range);
  };
  const Type& t = v.type;
  const bool quantity = t.is_floating() && !t.is_array() && (t.shape == Shape::scalar || t.shape == Shape::vector) &&
                        (t.geometry == Geometry::none || t.geometry == Geometry::spectrum || t.geometry == Geometry::vector);
  if (!quantity)
    return fail("cannot convert " + name_of(t) + " to " + unit_text + ": only quantities (float, vecN, spectrum, vector) have units",
                t.geometry == Geometry::point ? "a point's coordinates are lengths in the reference unit; convert its difference "
                                                "from another point, a vector"
                                              : "",
                code::E_TYPE_MISMATCH);
  Value out = v;
  out.range = e.range;
  out.lvalue = false;
  out.origin.reset();
  out.literal = false;
  out.constant.reset();
  ConversionInfo info;
  if (v.zero) {  // zero is zero in every unit
    result_.conversions[&e] = info;
    return out;
  }
  const DimSlot from = value_dimension(t, reg);
  if (from.state != DimSlot::State::known)
    return fail("cannot convert " + name_of(t) + " to " + unit_text + ": its dimension is not known here",
                from.state == DimSlot::State::generic ? "a generic quantity has no unit to convert from"
                                                      : "annotate it first, e.g. float<" + reg.format(*reg.reference(target)) + ">(x)",
                code::E_DIMENSION_MISMATCH);
  Checked<Dimension> have = reg.reference(from.value), want = reg.reference(target);
  if (!have || !want || !(*have == *want)) {
    std::string hint = want && have ? physics_hint(DimSlot::known(*want), DimSlot::known(*have)) : "";
    // `r * r in (meter^2)` converts only the right-hand r: say so when the target is a power of the operand.
    bool power_of_operand = false;
    for (int k : {2, 3, -1, -2})
      if (have && want && !have->is_dimensionless()) {
        Checked<Dimension> p = power(*have, k);
        power_of_operand = power_of_operand || (p && *p == *want);
      }
    if (power_of_operand)
      hint = "'in' binds tighter than '*' and '/': (a * b) in " + conversion_target(target) + " converts a product";
    return fail("cannot convert " + name_of(t) + " to " + unit_text + ": " + unit_text + " measures " +
                    (want ? reg.format(*want) : std::string("?")),
                hint, code::E_DIMENSION_MISMATCH);
  }
  info.factor = reg.scale(from.value) / reg.scale(target);
  out.type.dim = DimSlot::known(target);
  if (out.number) out.number = *out.number * info.factor;
  result_.conversions[&e] = info;
  return out;
}

Value Checker::convert_space(const ast::ConvertExpr& e, const Value& v, const SpaceSlot& target) {
  const Type& t = v.type;
  const Geometry kind = t.geometry;
  const std::string target_text = name_of_space(target);
  auto fail = [&](const std::string& message, const std::string& hint, std::vector<Diagnostic> notes = {}) {
    Diagnostic d = Diagnostic::error(e.range, message).with_code(code::E_SPACE_MISMATCH).with_highlight(e.operand->range);
    add_origin_note(d, v);
    for (Diagnostic& n : notes) d.with_note(std::move(n));
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
    return error_value(e.range);
  };
  const bool convertible = !t.is_array() && t.shape == Shape::vector &&
                           ((kind == Geometry::hpoint && t.rows == 4) ||
                            (t.rows == 3 && (kind == Geometry::point || kind == Geometry::vector || kind == Geometry::direction ||
                                             kind == Geometry::normal)));
  if (!convertible || t.from.state == SpaceSlot::State::unknown)
    return fail("cannot convert " + name_of(t) + " to " + target_text + ": " +
                    (convertible ? "it has no space" : "only points, vectors, directions, normals and hpoints are in a space"),
                t.shape == Shape::vector && t.rows == 3 && kind == Geometry::none
                    ? "say which kind and space it is in first, e.g. vector<S>(v) in " + target_text
                    : "");
  Value out = v;
  out.range = e.range;
  out.lvalue = false;
  out.origin.reset();
  ConversionInfo info;
  if (t.from == target) {  // already there
    result_.conversions[&e] = info;
    return out;
  }

  // The map variables in scope (innermost declaration of each name), in declaration order.
  std::vector<MapEdge> edges;
  {
    std::vector<const Variable*> seen;
    std::vector<std::string> names;
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
      for (const auto& [n, var] : *scope) {
        if (std::find(names.begin(), names.end(), n) != names.end()) continue;
        names.push_back(n);
        if (is_map(var.type.geometry) && !var.type.is_array() && var.type.from.state != SpaceSlot::State::unknown &&
            var.type.to.state != SpaceSlot::State::unknown && !(var.type.from == var.type.to))
          seen.push_back(&var);
      }
    std::sort(seen.begin(), seen.end(), [](const Variable* a, const Variable* b) {
      return std::tie(a->range.begin.file, a->range.begin.offset, a->name) < std::tie(b->range.begin.file, b->range.begin.offset, b->name);
    });
    for (const Variable* var : seen) edges.push_back({var, var->type.geometry, var->type.from, var->type.to});
  }

  // Breadth-first over (space, homogeneous): the shortest chains, and how many there are.
  struct Reached {
    int depth = 0;
    int paths = 0;  // saturates at 2
    std::vector<std::pair<Node, const MapEdge*>> from;  // predecessors on shortest chains
  };
  std::map<Node, Reached> reached;
  const Node start{t.from, kind == Geometry::hpoint};
  reached[start] = {0, 1, {}};
  std::vector<Node> layer{start};
  std::vector<Node> goals;
  for (int depth = 1; !layer.empty() && goals.empty(); ++depth) {
    std::vector<Node> next;
    for (const Node& n : layer)
      for (const MapEdge& edge : edges) {
        if (!(edge.from == n.space) || !edge_applies(edge, kind, n.homogeneous)) continue;
        const Node m{edge.to, n.homogeneous || edge.kind == Geometry::projmap};
        auto [it, fresh] = reached.try_emplace(m, Reached{depth, 0, {}});
        if (it->second.depth != depth) continue;  // reached by a shorter chain
        it->second.paths = std::min(2, it->second.paths + reached[n].paths);
        it->second.from.push_back({n, &edge});
        if (fresh) next.push_back(m);
      }
    for (const Node& m : next)
      if (m.space == target) goals.push_back(m);
    layer = std::move(next);
  }

  // One chain to `goal` per choice of predecessor (enough for the message: at most two).
  auto chains_to = [&](const Node& goal) {
    std::vector<std::vector<const MapEdge*>> out;
    std::vector<std::pair<Node, std::vector<const MapEdge*>>> stack{{goal, {}}};
    while (!stack.empty() && out.size() < 2) {
      auto [n, suffix] = stack.back();
      stack.pop_back();
      if (n == start) {
        std::reverse(suffix.begin(), suffix.end());
        out.push_back(suffix);
        continue;
      }
      const auto& preds = reached[n].from;
      for (auto p = preds.rbegin(); p != preds.rend(); ++p) {  // popped in declaration order
        std::vector<const MapEdge*> s = suffix;
        s.push_back(p->second);
        stack.push_back({p->first, s});
      }
    }
    return out;
  };

  const std::string subject = name_of(t) + (v.name.empty() ? std::string() : " '" + v.name + "'");
  if (goals.empty()) {
    std::string maps;
    for (const MapEdge& edge : edges) maps += (maps.empty() ? "" : ", ") + arrow(edge, *this);
    std::string from_spaces;
    for (const auto& [n, r] : reached)
      if (!n.homogeneous) from_spaces += (from_spaces.empty() ? "" : ", ") + name_of_space(n.space);
    std::string hint = maps.empty() ? "no map is in scope here" : "maps in scope: " + maps;
    hint += "; declare a map from " + (from_spaces.empty() ? name_of_space(t.from) : from_spaces) + " to " + target_text;
    bool projective_exit = false;
    for (const MapEdge& edge : edges)
      for (const auto& [n, r] : reached) projective_exit = projective_exit || (edge.kind == Geometry::projmap && edge.from == n.space);
    if (projective_exit && kind != Geometry::point && kind != Geometry::hpoint)
      hint += " (a projmap applies only to points)";
    // A map that would finish the chain the other way round: 'in' does not invert maps.
    for (const MapEdge& edge : edges) {
      if (edge.kind == Geometry::projmap) continue;
      // Into the value's space when no map leaves it (world → light for a point in light), or out of the
      // target into a space reached.
      const bool into_value = reached.size() == 1 && edge.to == t.from && !(edge.from == t.from);
      if (!into_value && (!(edge.from == target) || !reached.count(Node{edge.to, false}))) continue;
      hint += "; '" + edge.variable->name + "' goes the other way (" + name_of_space(edge.from) + " → " + name_of_space(edge.to) +
              ") and 'in' does not invert maps: declare its inverse, or write inverse(" + edge.variable->name + ") * …";
      break;
    }
    return fail("cannot convert " + subject + " to " + target_text + ": no chain of maps in scope leads from " +
                    name_of_space(t.from) + " to " + target_text,
                hint);
  }
  int paths = 0;
  for (const Node& g : goals) paths += reached[g].paths;
  std::vector<std::vector<const MapEdge*>> chains;
  for (const Node& g : goals)
    for (auto& c : chains_to(g)) chains.push_back(std::move(c));
  if (paths > 1 && chains.size() > 1) {
    // A note at the first map where the two chains part.
    std::size_t part = 0;
    while (part + 1 < chains[0].size() && chains[0][part] == chains[1][part]) ++part;
    std::vector<Diagnostic> notes;
    for (std::size_t i = 0; i < 2; ++i) {
      const Variable& m = *chains[i][part]->variable;
      notes.push_back(Diagnostic::note(m.range, "candidate " + chain_text(chains[i]) + ": '" + m.name + "' declared here as " +
                                                    name_of(m.type)));
    }
    const std::string how_many = paths > 2 ? "several" : "two";
    const std::string what = chains[0].size() == 1 ? how_many + " maps"
                                                   : how_many + " chains of " + std::to_string(chains[0].size()) + " maps";
    return fail("cannot convert " + subject + " to " + target_text + ": " + what + " lead there, " + chain_text(chains[0]) +
                    " and " + chain_text(chains[1]),
                "apply the map you mean explicitly, e.g. " + chain_text(chains[0]) + " * " +
                    (v.name.empty() ? std::string("x") : v.name),
                std::move(notes));
  }

  // The one chain: the result kind follows the transform rules, map by map.
  const std::vector<const MapEdge*>& chain = chains.front();
  bool rigid = true;
  for (const MapEdge* edge : chain) {
    info.maps.push_back(edge->variable->name);
    rigid = rigid && edge->kind == Geometry::rigidmap;
  }
  std::reverse(info.maps.begin(), info.maps.end());  // as written: the last map applied is leftmost
  const bool projective = chain.back()->kind == Geometry::projmap;
  out.type.from = target;
  switch (kind) {
    case Geometry::point:
      info.op = projective ? GeometricOp::project : GeometricOp::transform_point;
      if (projective) {
        out.type = Type::vector_of(Scalar::float_, 4);
        out.type.geometry = Geometry::hpoint;
        out.type.from = target;
      }
      break;
    case Geometry::hpoint: info.op = GeometricOp::transform_homogeneous; break;
    case Geometry::normal: info.op = rigid ? GeometricOp::transform_vector : GeometricOp::transform_normal; break;
    case Geometry::direction:
      info.op = GeometricOp::transform_vector;
      if (!rigid) {  // a non-rigid map does not keep unit length
        out.type.geometry = Geometry::vector;
        out.type.dim = DimSlot::known(Dimension{});
      }
      break;
    default: info.op = GeometricOp::transform_vector; break;
  }
  result_.conversions[&e] = info;
  return out;
}

}  // namespace safegi::detail
