// Unit length (docs/language.md, "What spaces do not reach"). A fragment shader's
// `in normal<S>` is interpolated across the primitive, so it is shorter than 1 until
// normalize(); where its length matters (a cosine, a reflection, an offset along it, a
// declared normal or direction) the checker says so. And a unit direction's z in a
// normal-aligned frame is its cosine.

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
         (v.type.length_loss == Type::LengthLoss::scaled ? " carried by a normal matrix that may scale"
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
  if (name != "dot" && name != "reflect" && name != "refract" && name != "faceforward") return true;
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i].type.length_loss != Type::LengthLoss::none) {
      report_not_unit(args[i], "argument " + std::to_string(i + 1) + " of '" + name + "' is");
      return false;
    }
  return true;
}

// A user function's normal or direction parameter takes a unit vector.
bool Checker::unit_length_parameters(const std::string& callee, const std::vector<Type>& params, const std::vector<Value>& args) {
  for (std::size_t i = 0; i < args.size() && i < params.size(); ++i) {
    const Geometry want = params[i].geometry;
    if (args[i].type.length_loss != Type::LengthLoss::none && (want == Geometry::normal || want == Geometry::direction)) {
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

}  // namespace safegi::detail
