// Dimension rules beyond the exponent algebra (docs/language.md, "Cosines"
// and "Units"): where a cosine stops being a projection factor, and
// radians()/degrees() of an angle measured in a unit.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// The exponent of the base `proj` in `d`, or 0 when the program has no proj.
int proj_exponent(const Dimension& d, const DimensionRegistry& reg) {
  std::optional<BaseId> proj = reg.find_base("proj");
  if (!proj) return 0;
  for (const Factor& f : d.factors())
    if (f.base == *proj) return f.exponent;
  return 0;
}

// The unit the program measures degrees in (the prelude's `degree`), if any.
const Unit* degree_unit(const DimensionRegistry& reg) {
  std::optional<Dimension> angle = reg.find_dimension("angle");
  if (!angle) return nullptr;
  for (const Unit& u : reg.units())
    if (u.dimension == *angle && DimensionRegistry::same_scale(u.scale, std::numbers::pi / 180.0)) return &u;
  return nullptr;
}

}  // namespace

// A pure power of proj (cos θ, cos² θ) where a plain number is expected: the
// cosine is used as a number (Schlick's 1 - cos θ, GGX's cos² θh (α² - 1) + 1,
// Smith's masking term, a lobe's pow), not as the projection of an area.
// Never the reverse: a plain number where proj is expected stays the missing
// cosine it usually is.
bool Checker::cosine_as_number(const DimSlot& expected, const DimSlot& found) const {
  if (expected.state != DimSlot::State::known || found.state != DimSlot::State::known) return false;
  if (!expected.value.is_dimensionless() || found.value.factors().size() != 1) return false;
  return proj_exponent(found.value, result_.registry) > 0;
}

// A cosine scaling a unit vector is a component along it (the reflection
// 2 (n·w) n - w, Gram–Schmidt t - (t·n) n): the product keeps the scale's
// dimension without one proj.
DimSlot Checker::projected_component(const DimSlot& scale) const {
  if (scale.state != DimSlot::State::known || proj_exponent(scale.value, result_.registry) <= 0) return scale;
  Checked<Dimension> d = divide(scale.value, Dimension::base(*result_.registry.find_base("proj"), 1));
  return d ? DimSlot::known(*d) : scale;
}

// A plain number made with a multiple of π (2.0 * PI * u, the azimuth of a sample; x * PI / 180.0)
// is an angle in radians for sin, cos and tan: writing the unit would restate the π. A plain
// number without one (sin(0.5), sin(angleInDegrees)) still asks: radians or degrees?
void Checker::radians_of_pi_multiple(const std::string& name, std::vector<Value>& args) const {
  if ((name != "sin" && name != "cos" && name != "tan") || args.size() != 1) return;
  const std::optional<Dimension> angle = result_.registry.find_dimension("angle");
  // A plain number times a π constant is radians; divided by one (1.0 / PI), it is no angle.
  if (const std::optional<PiFactor>& pi = args[0].pi_factor;
      pi && pi->known.is_known() && pi->known.value.is_dimensionless() && angle &&
      value_dimension(args[0].type, result_.registry).state == DimSlot::State::unknown) {
    args[0].type.dim = DimSlot::known(pi->exponent == 1 ? *angle : Dimension{});
    return;
  }
  if (!args[0].pi_multiple) return;
  const DimSlot d = value_dimension(args[0].type, result_.registry);
  if (d.is_known() && d.value.is_dimensionless() && angle) args[0].type.dim = DimSlot::known(*angle);
}

// The same number stored into a declared angle (`float<angle> phi = 2.0 * PI * u;`): radians.
std::optional<Value> Checker::pi_multiple_as_angle(const Type& target, const Value& value) const {
  if (!value.pi_multiple || target.shape != Shape::scalar || target.is_array()) return std::nullopt;
  const std::optional<Dimension> angle = result_.registry.find_dimension("angle");
  const DimSlot want = value_dimension(target, result_.registry), have = value_dimension(value.type, result_.registry);
  if (!angle || !want.is_known() || !have.is_known() || !have.value.is_dimensionless()) return std::nullopt;
  const Checked<Dimension> reference = result_.registry.reference(want.value);
  if (!reference || *reference != *angle) return std::nullopt;
  Value radians = value;
  radians.type.dim = DimSlot::known(*angle);
  radians.pi_multiple = false;
  return radians;
}

// A quantity in a unit times the plain number that is that unit's scale is the quantity in
// reference units: the conversion written out (`fov * (3.14159265 / 180.0)` of an angle in
// degrees is radians, `lengthCm * 0.01` metres), as `x in radian` would give it.
std::optional<DimSlot> Checker::conversion_written_out(const Value& a, const DimSlot& da, const Value& b, const DimSlot& db) const {
  const DimensionRegistry& reg = result_.registry;
  for (int side = 0; side < 2; ++side) {
    const DimSlot& quantity = side == 0 ? da : db;
    const Value& factor = side == 0 ? b : a;
    const DimSlot& factor_dim = side == 0 ? db : da;
    if (!quantity.is_known() || !reg.has_unit_factors(quantity.value) || !factor.number || !factor_dim.is_known() ||
        !factor_dim.value.is_dimensionless())
      continue;
    const double scale = reg.scale(quantity.value);
    if (scale <= 0.0 || std::fabs(*factor.number / scale - 1.0) > 1e-5) continue;
    if (Checked<Dimension> reference = reg.reference(quantity.value)) return DimSlot::known(*reference);
  }
  return std::nullopt;
}

bool is_pi_multiple(double value) {
  const double quarters = value / 3.141592653589793 * 4.0;
  return value != 0.0 && std::round(quarters) != 0.0 && std::fabs(quarters) <= 64.0 && std::fabs(quarters - std::round(quarters)) < 1e-4;
}

// radians(x) of an angle in degrees is the angle (in radians); degrees(x) of
// an angle is that angle in degrees. A plain number (radians(45.0)) takes the
// signature; so does anything else, for its error. An angle already in the
// target unit, or in a third one (arcminutes), is refused: the call scales by
// π/180 or 180/π, right for its own source unit only.
std::optional<Value> Checker::angle_conversion(const std::string& name, const Value& arg, const Type& result,
                                               SourceRange call_range) {
  const DimensionRegistry& reg = result_.registry;
  const Unit* degree = degree_unit(reg);
  std::optional<Dimension> angle = reg.find_dimension("angle");
  const DimSlot d = value_dimension(arg.type, reg);
  if (!degree || !angle || d.state != DimSlot::State::known) return std::nullopt;
  const Dimension in_degrees = reg.measured_in(*degree);
  const bool to_radians = name == "radians";
  const Dimension& source = to_radians ? in_degrees : *angle;
  const Dimension& target = to_radians ? *angle : in_degrees;
  if (d.value == source) {
    Value out;
    out.range = call_range;
    out.type = result;
    out.type.geometry = arg.type.geometry == Geometry::spectrum ? Geometry::spectrum : Geometry::none;
    out.type.dim = DimSlot::known(target);
    return out;
  }
  const Checked<Dimension> measured = reg.reference(d.value);
  const bool another_unit = reg.has_unit_factors(d.value) && measured && *measured == *angle;
  const bool already = d.value == target;
  const bool plain_radians = !to_radians && d.value.is_dimensionless() && !arg.zero;
  if (!already && !another_unit && !plain_radians) return std::nullopt;
  const std::string argument = arg.name.empty() ? "x" : arg.name;
  const std::string has_type = "argument 1 of '" + name + "' has type " + name_of(arg.type);
  std::string message, hint;
  if (already) {
    message = has_type + ", which is already in " + name;
    hint = to_radians ? "radians() converts degrees (a plain number or float<angle in degree>); use the angle as it is"
                      : "degrees() converts radians; use the angle as it is";
  } else if (another_unit) {
    message = has_type + ", but '" + name + "' converts an angle in " + (to_radians ? "degrees (or a plain number of degrees)" : "radians");
    hint = "an angle in " + reg.format_units(d.value) + " converts with in: " + argument + " in " + conversion_target(target) +
           " (× " + DimensionRegistry::format_number(reg.scale(d.value) / reg.scale(target)) + ")";
  } else {
    message = has_type + ", but 'degrees' expects float<angle>";
    hint = "degrees() converts an angle in radians: give a plain number of radians its unit, degrees(" + argument + " * " + conversion_target(*angle) + ")";
  }
  Diagnostic e = Diagnostic::error(arg.range, message).with_code(code::E_DIMENSION_MISMATCH);
  add_origin_note(e, arg);
  e.with_hint(hint);
  report(std::move(e));
  return error_value(call_range);
}

}  // namespace safegi::detail

namespace safegi::detail {

namespace {

// "π", "2π", "π/2", "3π/4": k of kπ in quarters, as the π rules take them.
std::string pi_text(double multiple) {
  const long long quarters = std::llround(std::fabs(multiple) * 4.0);
  long long num = quarters, den = 4;
  while (den > 1 && num % 2 == 0) num /= 2, den /= 2;
  std::string text = (multiple < 0 ? "-" : "") + (num == 1 ? std::string() : std::to_string(num)) + "π";
  return den == 1 ? text : text + "/" + std::to_string(den);
}

// X of `known · X^exponent` = `whole`: the quantity π is when the product is `whole`.
Checked<Dimension> pi_quantity(const PiFactor& pi, const Dimension& whole) {
  const Checked<Dimension> x = divide(whole, pi.known.value);
  return x && pi.exponent < 0 ? divide(Dimension{}, *x) : x;
}

std::optional<Dimension> projected_solid_angle(const DimensionRegistry& registry) {
  const std::optional<Dimension> sr = registry.find_dimension("solid_angle"), proj = registry.find_dimension("proj");
  if (!sr || !proj) return std::nullopt;
  Checked<Dimension> product = multiply(*sr, *proj);
  return product ? std::optional<Dimension>(*product) : std::nullopt;
}

}  // namespace

// kπ is a plain number (πr², 4πr²) or radians for any k; steradians as the hemisphere (2π) or the
// sphere (4π); projected steradians as the cosine-weighted hemisphere (π) and the lobe normalisations
// written with 2π, 4π, 8π (Phong's (n + 2)/2π, Blinn's (n + 8)/8π).
bool pi_can_measure(double multiple, const Dimension& x, const DimensionRegistry& registry) {
  if (x.is_dimensionless()) return true;
  const Checked<Dimension> reference = registry.reference(x);
  // kπ is radians, steradians …: a quantity measured in another unit (degrees) is no multiple of π.
  if (reference && !(*reference == x)) return false;
  const Dimension& q = x;
  const auto one_of = [&](std::initializer_list<double> ks) {
    return std::any_of(ks.begin(), ks.end(), [&](double k) { return std::fabs(std::fabs(multiple) - k) < 1e-6; });
  };
  if (const std::optional<Dimension> angle = registry.find_dimension("angle"); angle && q == *angle) return true;
  if (const std::optional<Dimension> sr = registry.find_dimension("solid_angle"); sr && q == *sr) return one_of({2, 4});
  if (const std::optional<Dimension> psa = projected_solid_angle(registry); psa && q == *psa) return one_of({1, 2, 4, 8});
  return false;
}

// How products, quotients and sums of values carrying the same π constant (PiFactor) go: products
// add the exponents (π / π cancels to a known dimension), a sum with a known dimension decides the
// quantity π is there, and two sides no quantity π measures can make agree are an error.
bool Checker::carry_pi_factor(ast::BinaryOp op, const Value& lhs, const Value& rhs, Value& out, SourceRange op_range) {
  const DimensionRegistry& reg = result_.registry;
  if (out.type.is_error() || value_dimension(out.type, reg).is_known()) return true;
  const bool product = op == ast::BinaryOp::Mul || op == ast::BinaryOp::Div;
  const bool sum = op == ast::BinaryOp::Add || op == ast::BinaryOp::Sub;
  if (!product && !sum) return true;
  const std::optional<PiFactor>& a = lhs.pi_factor;
  const std::optional<PiFactor>& b = rhs.pi_factor;
  const DimSlot da = value_dimension(lhs.type, reg), db = value_dimension(rhs.type, reg);
  const int sign = op == ast::BinaryOp::Div ? -1 : 1;
  if (product && a && b) {
    if (a->name != b->name || !a->known.is_known() || !b->known.is_known()) return true;
    const std::optional<DimSlot> known = combine(a->known, b->known, sign);
    if (!known || !known->is_known()) return true;
    PiFactor pi = *a;
    pi.exponent = a->exponent + sign * b->exponent;
    pi.known = *known;
    if (pi.exponent == 0) out.type.dim = *known;  // kπ / kπ: whichever quantity, it cancels
    else out.pi_factor = pi;
    return true;
  }
  if (product && (a || b)) {
    const DimSlot& other = a ? db : da;
    if (!other.is_known()) return true;
    PiFactor pi = a ? *a : *b;
    const std::optional<DimSlot> known = a ? combine(pi.known, other, sign) : combine(other, pi.known, sign);
    if (!known || !known->is_known()) return true;
    if (!a && op == ast::BinaryOp::Div) pi.exponent = -pi.exponent;
    pi.known = *known;
    // A literal factor is part of the multiple: 4.0 * PI is 4π, 1.0 / (2.0 * PI) is 1/(2π), PI / 2.0 is π/2.
    const Value& factor = a ? rhs : lhs;
    if (factor.literal && factor.number && *factor.number != 0.0 && !factor.pi_factor) {
      const bool divides_pi = a && op == ast::BinaryOp::Div;  // PI / c
      const double c = divides_pi ? 1.0 / *factor.number : *factor.number;
      // c · (kπ)^e: k·c for e = 1, k/c for e = −1.
      pi.multiple = pi.exponent > 0 ? pi.multiple * c : pi.multiple / c;
    }
    // An angle divided by π (`theta / PI`, a lat-long map's u = φ / 2π, an angle normalised to [0, 1]) is
    // divided by π radians: a plain fraction, decided here so that adding it to an angle is refused.
    if (const std::optional<Dimension> angle = reg.find_dimension("angle");
        angle && pi.exponent == -1 && pi.known.is_known() && pi.known.value == *angle) {
      out.type.dim = DimSlot::known(Dimension{});
      return true;
    }
    out.pi_factor = pi;
    return true;
  }
  if (!sum) return true;
  // A sum: the side of known dimension says what π is on the other.
  if ((a && !b && da.state == DimSlot::State::unknown && db.is_known()) ||
      (b && !a && db.state == DimSlot::State::unknown && da.is_known())) {
    const Value& with_pi = a ? lhs : rhs;
    const DimSlot& known = a ? db : da;
    Type target = out.type;
    target.dim = known;
    if (std::optional<DimSlot> as_pi = pi_factor_misfit(target, with_pi)) {
      Diagnostic d = Diagnostic::error(op_range, std::string("cannot ") + (op == ast::BinaryOp::Add ? "add " : "subtract ") +
                                                     "a value of dimension " + reg.format(known.value) + " and one that is " +
                                                     reg.format(as_pi->value) + ", taking '" + with_pi.pi_factor->name + "' as " +
                                                     pi_reading(*with_pi.pi_factor, *as_pi) + ": no quantity π measures makes them agree")
                         .with_code(code::E_DIMENSION_MISMATCH);
      d.with_highlight(lhs.range).with_highlight(rhs.range);
      d.with_hint(physics_hint(known, *as_pi));
      report(std::move(d));
      return false;
    }
    out.type.dim = known;
    return true;
  }
  // Two π constants are the same π (`HALF_PI - QUARTER_PI * r`, two literals): a sum of them is one.
  if (a && b && a->exponent == b->exponent && a->known.is_known() && b->known.is_known()) {
    if (same_dimension(a->known, b->known)) {
      out.pi_factor = a;
      return true;
    }
    Diagnostic d = Diagnostic::error(op_range, std::string("cannot ") + (op == ast::BinaryOp::Add ? "add " : "subtract ") +
                                                   "values of dimension " + reg.format(a->known.value) + " and " +
                                                   reg.format(b->known.value) + ", each times the same power of '" + a->name +
                                                   "': they differ whatever quantity π is")
                       .with_code(code::E_DIMENSION_MISMATCH);
    d.with_highlight(lhs.range).with_highlight(rhs.range);
    // They differ by what π itself can be (Lambert's 1/π applied on one side only): say so.
    const Checked<Dimension> ratio = divide(a->known.value, b->known.value);
    const Checked<Dimension> inverse = ratio ? divide(Dimension{}, *ratio) : ratio;
    if (ratio && inverse && (pi_can_measure(a->multiple, *ratio, reg) || pi_can_measure(a->multiple, *inverse, reg)))
      d.with_hint("they differ by one factor of " + pi_text(a->multiple) + " (as " +
                  reg.format(pi_can_measure(a->multiple, *ratio, reg) ? *ratio : *inverse) +
                  "): a division by '" + a->name + "' on one side only, or a multiplication missing on the other?");
    report(std::move(d));
    return false;
  }
  return true;
}

std::optional<DimSlot> Checker::pi_factor_misfit(const Type& target, const Value& value) const {
  if (!value.pi_factor || std::abs(value.pi_factor->exponent) != 1 || !value.pi_factor->known.is_known()) return std::nullopt;
  const DimensionRegistry& reg = result_.registry;
  const DimSlot want = value_dimension(target, reg);
  if (!want.is_known() || value_dimension(value.type, reg).state != DimSlot::State::unknown) return std::nullopt;
  const PiFactor& pi = *value.pi_factor;
  const Checked<Dimension> x = pi_quantity(pi, want.value);
  if (!x || pi_can_measure(pi.multiple, *x, reg)) return std::nullopt;
  // A radiometric target (steradians or proj in it) reads π as a lobe's or a pdf's projected
  // steradians where kπ can be that; any other, as the plain number (4πr² for an area).
  const auto reading = [&](const Dimension& as) -> std::optional<Dimension> {
    Checked<Dimension> power = as;
    if (pi.exponent < 0) power = divide(Dimension{}, as);
    Checked<Dimension> found = power ? multiply(pi.known.value, *power) : power;
    return found ? std::optional<Dimension>(*found) : std::nullopt;
  };
  // A reading that makes the value the inverse of the target says the likeliest mistake: a measure
  // (4π sr, the sphere) where its density (1/(4π) per steradian) belongs, or the other way.
  const std::optional<Dimension> sr = reg.find_dimension("solid_angle");
  const std::optional<Dimension> psa = projected_solid_angle(reg);
  for (const std::optional<Dimension>& as : {sr, psa}) {
    if (!as || !pi_can_measure(pi.multiple, *as, reg)) continue;
    const std::optional<Dimension> found = reading(*as);
    if (!found || found->is_dimensionless()) continue;
    const Checked<Dimension> product = multiply(*found, want.value);
    if (product && product->is_dimensionless()) return DimSlot::known(*found);
  }
  // A target per steradian without proj (an intensity, a phase function) reads π as steradians,
  // though no solid angle is that multiple of it; another radiometric target (steradians or proj in
  // it) reads π as a lobe's or a pdf's projected steradians where kπ can be that; any other, as the
  // plain number (4πr² for an area).
  bool radiometric = false, projected = false, per_steradian = false;
  for (const Factor& f : want.value.factors()) {
    if (psa && psa->exponent(f.base) != 0) radiometric = true;
    if (sr && sr->exponent(f.base) != 0) per_steradian = true;
    else if (psa && psa->exponent(f.base) != 0) projected = true;
  }
  Dimension as{};
  // A bare density per steradian (a pdf) keeps the projected reading: cos θ / π without its cosine.
  const Checked<Dimension> per_sr = sr ? divide(Dimension{}, *sr) : Checked<Dimension>(Dimension{});
  if (per_steradian && !projected && sr && !(per_sr && want.value == *per_sr)) as = *sr;
  else if (radiometric && pi_can_measure(pi.multiple, *psa, reg)) as = *psa;
  const std::optional<Dimension> found = reading(as);
  if (!found) return std::nullopt;
  return DimSlot::known(*found);
}

// "π projected steradians", "the plain number 2π".
std::string Checker::pi_reading(const PiFactor& pi, const DimSlot& as) const {
  const std::string k = pi_text(pi.multiple);
  const std::optional<Dimension> psa = projected_solid_angle(result_.registry);
  const Checked<Dimension> x = pi_quantity(pi, as.value);
  if (x && psa && *x == *psa)
    return k + " projected steradians" + (std::fabs(std::fabs(pi.multiple) - 1) < 1e-6 ? " (the cosine-weighted hemisphere)" : "");
  const std::optional<Dimension> sr = result_.registry.find_dimension("solid_angle");
  if (x && sr && *x == *sr) {
    const double m = std::fabs(pi.multiple);
    return k + " steradians" + (std::fabs(m - 4) < 1e-6 ? " (the sphere)" : std::fabs(m - 2) < 1e-6 ? " (the hemisphere)" : "");
  }
  return "the plain number " + k;
}

std::optional<PiFactor> pi_constant(const std::string& name, double value) {
  if (is_pi_multiple(value)) return PiFactor{name, value / std::numbers::pi, 1, DimSlot::known(Dimension{})};
  if (value != 0.0 && is_pi_multiple(1.0 / value))
    return PiFactor{name, 1.0 / (value * std::numbers::pi), -1, DimSlot::known(Dimension{})};
  return std::nullopt;
}

}  // namespace safegi::detail
