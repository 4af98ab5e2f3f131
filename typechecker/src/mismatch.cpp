// Physics-aware hints for dimension and space mismatches, and the notes that
// say where an operand's annotation came from.

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {

std::string format_number(double value) { return DimensionRegistry::format_number(value); }

std::string Checker::conversion_target(const Dimension& d) const {
  const std::string units = result_.registry.format_units(d, Notation::ascii);
  if (units.find_first_of("*/^") == std::string::npos) return units;
  return "(" + units + ")";
}

std::string Checker::unit_hint(const Dimension& expected, const Dimension& found) const {
  const DimensionRegistry& reg = result_.registry;
  Checked<Dimension> e = reg.reference(expected), f = reg.reference(found);
  if (!e || !f) return {};
  if (!(*e == *f)) return physics_hint(DimSlot::known(*e), DimSlot::known(*f));  // the dimensions differ too
  const double factor = reg.scale(found) / reg.scale(expected);
  return "the same " + reg.format(*e) + " in another unit, " + reg.format_units(found) + " where " + reg.format_units(expected) +
         " is expected: convert it, x in " + conversion_target(expected) + " (× " + format_number(factor) + ")";
}

std::string Checker::physics_hint(const DimSlot& expected, const DimSlot& found) const {
  if (expected.state != DimSlot::State::known || found.state != DimSlot::State::known) return {};
  const DimensionRegistry& reg = result_.registry;
  if (reg.has_unit_factors(expected.value) || reg.has_unit_factors(found.value)) return unit_hint(expected.value, found.value);
  Checked<Dimension> ratio = divide(found.value, expected.value);  // what the value has too much of
  if (!ratio) return {};
  const Dimension& r = *ratio;
  auto base = [&](const char* name) -> std::optional<BaseId> { return reg.find_base(name); };
  auto is = [&](std::initializer_list<std::pair<const char*, int>> factors) {
    std::vector<Factor> want;
    for (const auto& [name, e] : factors) {
      std::optional<BaseId> b = base(name);
      if (!b) return false;
      want.push_back({*b, e});
    }
    Checked<Dimension> d = Dimension::from_factors(want);
    return d && *d == r;
  };
  if (is({{"proj", -1}})) return "the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?";
  if (is({{"proj", 1}})) return "the value has an extra factor of proj: is a cosine applied twice?";
  if (is({{"solid_angle", -1}})) return "the value lacks a factor of solid_angle: missing division by a pdf?";
  if (is({{"solid_angle", 1}})) return "the value has an extra factor of solid_angle: divided by a pdf twice, or multiplied where it should divide?";
  if (is({{"solid_angle", -2}})) return "the value lacks solid_angle²: multiplied by a pdf where it should divide by it?";
  if (is({{"length", 2}, {"solid_angle", -1}}) || is({{"length", 2}, {"solid_angle", -1}, {"proj", -1}}) ||
      is({{"length", 2}, {"solid_angle", -1}, {"proj", 1}}))
    return "a pdf per area where a pdf per solid angle is needed (or the reverse): missing r²/cos Jacobian?";
  if (is({{"length", -2}, {"solid_angle", 1}}) || is({{"length", -2}, {"solid_angle", 1}, {"proj", 1}}) ||
      is({{"length", -2}, {"solid_angle", 1}, {"proj", -1}}))
    return "a pdf per solid angle where a pdf per area is needed (or the reverse): missing r²/cos Jacobian?";
  if (is({{"solid_angle", -1}, {"proj", -1}}))
    return "radiance where irradiance is expected: integrate over projected solid angle (× cos θ dω) to get irradiance";
  if (is({{"solid_angle", 1}, {"proj", 1}}))
    return "irradiance where radiance is expected: reflect it with a brdf (1/(solid_angle·proj)) to get radiance";
  if (is({{"length", 2}})) return "the value has an extra factor of area: missing division by the squared distance?";
  if (is({{"length", -2}})) return "the value lacks a factor of area: divided by the squared distance twice?";
  if (is({{"angle", -1}}))
    return "a plain number where an angle is expected: radians or degrees? Use radians(x) or write the unit, x * degree";
  if (is({{"angle", 1}})) return "an angle where a plain number is expected: did you mean its sine or cosine, or degrees(x)?";
  if (found.value.is_dimensionless()) {
    for (const Unit& unit : reg.units())
      if (unit.dimension == expected.value)
        return "a plain number where " + reg.format(expected.value) + " is expected: give it a unit, e.g. x * " + unit.name;
    return "a plain number where " + reg.format(expected.value) + " is expected: convert it explicitly if it is one";
  }
  if (expected.value.is_dimensionless())
    return "the value has dimension " + reg.format(found.value) + " where a plain number is expected";
  return "the value differs from " + reg.format(expected.value) + " by a factor of " + reg.format_product(r);
}

std::string Checker::space_hint(const SpaceSlot& expected, const SpaceSlot& found) const {
  const DimensionRegistry& reg = result_.registry;
  auto name = [&](const SpaceSlot& s) -> std::optional<std::string> {
    if (s.state != SpaceSlot::State::known || s.id >= reg.spaces().size()) return std::nullopt;
    return reg.space_name(s.id);
  };
  std::optional<std::string> from = name(found), to = name(expected);
  if (!from || !to) return {};
  return "missing transform by map<" + *from + ", " + *to + ">?";
}

std::string Checker::compose_hint(const Type& left, const Type& right) const {
  const std::string order = "maps compose right to left: in m2 * m1, m1 is applied first";
  if (consistent(left.to, right.from) && left.to.state != SpaceSlot::State::unknown)
    return "the operands are in the wrong order (" + order + ")";
  if (right.from == left.from && right.from.state != SpaceSlot::State::unknown)
    return "the right-hand map goes the other way: its inverse, a map<" + name_of_space(right.to) + ", " +
           name_of_space(right.from) + ">, would meet the left-hand one";
  return "the right-hand map must end in " + name_of_space(left.from) + " (" + order + ")";
}

void Checker::add_origin_note(Diagnostic& d, const Value& v) const {
  if (!v.origin || !v.origin->range.valid() || !v.type.is_annotated()) return;
  d.with_note(Diagnostic::note(v.origin->range, v.origin->text + " as " + name_of(v.type)));
}

}  // namespace safegi::detail
