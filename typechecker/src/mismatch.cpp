// Physics-aware hints for dimension and space mismatches, and the notes that
// say where an operand's annotation came from.

#include <tuple>
#include <safegi/parser/printer.hpp>
#include <safegi/parser/walk.hpp>
#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {

std::string format_number(double value) { return DimensionRegistry::format_number(value); }

std::string Checker::conversion_target(const Dimension& d) const {
  const std::string units = result_.registry.format_units(d, Notation::ascii);
  if (d.is_dimensionless()) return "(1)";  // `x in 1` does not parse
  if (units.find_first_of("*/^") == std::string::npos) return units;
  return "(" + units + ")";
}

std::string Checker::unit_hint(const Dimension& expected, const Dimension& found, SourceRange found_range,
                               const std::string& found_spelling) const {
  const DimensionRegistry& reg = result_.registry;
  Checked<Dimension> e = reg.reference(expected), f = reg.reference(found);
  if (!e || !f) return {};
  if (!(*e == *f)) {  // the dimensions differ too; `inv_length in kilometer⁻¹` is still an inv_length
    const std::size_t in = found_spelling.find(" in ");
    return physics_hint(DimSlot::known(*e), DimSlot::known(*f, in == std::string::npos ? std::string() : found_spelling.substr(0, in)),
                        found_range);
  }
  const double factor = reg.scale(found) / reg.scale(expected);
  std::string hint = "the same " + reg.format(*e) + " in another unit, " + reg.format_units(found) + " where " +
                     reg.format_units(expected) + " is expected: convert it, x in " + conversion_target(expected) + " (× " +
                     format_number(factor) + ")";
  // In a product (ds / spotReachCm), the factor that brought the unit is where to convert.
  const std::vector<ProductFactor> factors = product_factors(found_range);
  for (const ProductFactor& f : factors) {
    if (factors.size() < 2 || f.name.empty() || f.unit || f.dim.state != DimSlot::State::known || !reg.has_unit_factors(f.dim.value))
      continue;
    if (Checked<Dimension> ref = reg.reference(f.dim.value))
      return hint + "; or convert '" + f.name + "' where it enters, " + f.name + " in " + conversion_target(*ref);
  }
  return hint;
}

// The factors of a product as written (`Kd * Li * cosI / pdf`), each with the
// dimension the checker gave it, so a hint can name the factor that is wrong.
// Errors are rare, so the expression is found by its range rather than
// threaded through every caller.
std::vector<Checker::ProductFactor> Checker::product_factors(SourceRange range) const {
  std::vector<ProductFactor> out;
  if (!range.valid()) return out;
  const ast::Expr* root = expression_at(range);
  std::vector<std::pair<const ast::Expr*, int>> todo;
  if (root) todo.emplace_back(root, 1);
  while (!todo.empty() && out.size() < 64) {
    auto [e, sign] = todo.back();
    todo.pop_back();
    if (const auto* paren = ast::dyn_cast<ast::ParenExpr>(e)) {
      todo.emplace_back(paren->inner, sign);
      continue;
    }
    if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(e); b && (b->op == ast::BinaryOp::Mul || b->op == ast::BinaryOp::Div)) {
      todo.emplace_back(b->rhs, b->op == ast::BinaryOp::Div ? -sign : sign);
      todo.emplace_back(b->lhs, sign);
      continue;
    }
    ProductFactor f;
    f.sign = sign;
    f.literal = ast::isa<ast::LiteralExpr>(e);
    if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e)) {
      f.name = id->name;
      f.unit = !lookup(id->name) && result_.registry.find_unit(id->name) != nullptr;
    } else if (const auto* m = ast::dyn_cast<ast::MemberExpr>(e)) {
      f.name = m->member;
    }
    const auto type = result_.types.find(e);
    if (type != result_.types.end()) f.dim = value_dimension(type->second, result_.registry);
    out.push_back(std::move(f));
  }
  return out;
}

// The first non-empty `match` of a node of `e`, walking on into the initialiser of each inferred
// local `e` names (`float cosL = max(dot(n, -dir), 0.0);` ... `L * cosL`), three locals deep.
std::string Checker::find_following_locals(const ast::Expr* e, const std::function<std::string(const ast::Node&)>& match,
                                           int depth) const {
  std::string found;
  if (e == nullptr) return found;
  ast::walk(e, [&](const ast::Node& n) {
    if (!found.empty()) return;
    if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(&n); id && depth < 3) {
      if (const Variable* v = lookup(id->name); v && !v->builtin && v->origin.inferred)
        found = find_following_locals(expression_at(v->origin.range), match, depth + 1);
      return;
    }
    found = match(n);
  });
  return found;
}

// In `e`, a dot(a, b) of a unit vector (direction or normal) and a vector of a space: "'b', a
// vector<S, 1>". Empty if there is none.
std::string Checker::non_unit_dot_operand(const ast::Expr* e) const {
  const auto geometry = [&](const ast::Expr* x) {
    const auto t = result_.types.find(x);
    return t == result_.types.end() ? Geometry::none : t->second.geometry;
  };
  return find_following_locals(e, [&](const ast::Node& n) -> std::string {
    const auto* call = ast::dyn_cast<ast::CallExpr>(&n);
    if (call == nullptr || call->callee != "dot" || call->args.size() != 2) return {};
    for (int i = 0; i < 2; ++i) {
      const Geometry unit = geometry(call->args[i]), other = geometry(call->args[1 - i]);
      if ((unit == Geometry::direction || unit == Geometry::normal) && other == Geometry::vector) {
        const auto t = result_.types.find(call->args[1 - i]);
        return "'" + print_expression(*call->args[1 - i]) + "', a " + name_of(t->second);
      }
    }
    return {};
  });
}

// The π constant an expression divides an angle by (`theta / PI`, `float n = (a + HALF_PI) / PI;`), or empty.
std::string Checker::angle_divided_by_pi(const ast::Expr* e) const {
  const std::optional<Dimension> angle = result_.registry.find_dimension("angle");
  if (!angle) return {};
  return find_following_locals(e, [&](const ast::Node& n) -> std::string {
    const auto* div = ast::dyn_cast<ast::BinaryExpr>(&n);
    if (div == nullptr || div->op != ast::BinaryOp::Div) return {};
    const auto* pi = ast::dyn_cast<ast::IdentifierExpr>(ast::without_parens(div->rhs));
    const Variable* constant = pi ? lookup(pi->name) : nullptr;
    const auto numerator = result_.types.find(div->lhs);
    const bool angle_over_pi = constant && constant->pi_constant && numerator != result_.types.end() &&
                               numerator->second.dim.is_known() && numerator->second.dim.value == *angle;
    return angle_over_pi ? pi->name : std::string();
  });
}

// An angle beside an angle divided by π (a fraction of π radians): one side was normalised, the other not.
std::optional<std::string> Checker::angle_fraction_hint(const Value& lhs, const Value& rhs) const {
  const std::optional<Dimension> angle = result_.registry.find_dimension("angle");
  if (!angle) return std::nullopt;
  const DimSlot da = value_dimension(lhs.type, result_.registry), db = value_dimension(rhs.type, result_.registry);
  for (const auto& [plain, other, dp, dother] : {std::tuple{&lhs, &rhs, da, db}, std::tuple{&rhs, &lhs, db, da}}) {
    if (!dp.is_known() || !dp.value.is_dimensionless() || !dother.is_known() || dother.value != *angle) continue;
    const std::string pi = angle_divided_by_pi(expression_at(plain->range));
    if (pi.empty()) continue;
    const std::string text = operand_text(*other, "the angle");
    return "'" + operand_text(*plain, "the other side") + "' is an angle divided by '" + pi + "', a fraction of " + pi +
           " radians: divide " + text + " by " + pi + " too (" + text + " / " + pi + ")";
  }
  return std::nullopt;
}

std::string Checker::physics_hint(const DimSlot& expected, const DimSlot& found, SourceRange found_range) const {
  if (expected.state != DimSlot::State::known || found.state != DimSlot::State::known) return {};
  const DimensionRegistry& reg = result_.registry;
  if (reg.has_unit_factors(expected.value) || reg.has_unit_factors(found.value))
    return unit_hint(expected.value, found.value, found_range, found.spelling);
  Checked<Dimension> ratio = divide(found.value, expected.value);  // what the value has too much of
  if (!ratio) return {};
  const Dimension& r = *ratio;
  // The value is the inverse of what is expected: a measure for its density (4π sr for 1/(4π) per
  // steradian), a pdf for its reciprocal.
  if (const Checked<Dimension> product = multiply(found.value, expected.value);
      product && product->is_dimensionless() && !found.value.is_dimensionless()) {
    const ast::Expr* e = expression_at(found_range);
    return "the value is the inverse of " + reg.format(expected.value) + ": inverted?" +
           (e ? " 1.0 / (" + print_expression(*e) + ")" : std::string());
  }
  auto make = [&](std::initializer_list<std::pair<const char*, int>> factors) -> std::optional<Dimension> {
    std::vector<Factor> want;
    for (const auto& [name, e] : factors) {
      std::optional<BaseId> b = reg.find_base(name);
      if (!b) return std::nullopt;
      want.push_back({*b, e});
    }
    Checked<Dimension> d = Dimension::from_factors(want);
    return d ? std::optional<Dimension>(*d) : std::nullopt;
  };
  auto is = [&](std::initializer_list<std::pair<const char*, int>> factors) {
    std::optional<Dimension> d = make(factors);
    return d && *d == r;
  };
  auto named = [&](const char* name, const Dimension& d) {
    std::optional<Dimension> n = reg.find_dimension(name);
    return n && *n == d;
  };
  const std::vector<ProductFactor> factors = product_factors(found_range);
  auto proj_of = [&](const ProductFactor& f) {
    std::optional<BaseId> proj = reg.find_base("proj");
    return proj && f.dim.state == DimSlot::State::known ? f.dim.value.exponent(*proj) : 0;
  };
  const bool plain_value = found.value.is_dimensionless();
  bool all_plain = !factors.empty();
  for (const ProductFactor& f : factors)
    all_plain = all_plain && (f.literal || (f.dim.state == DimSlot::State::known && f.dim.value.is_dimensionless()));
  const std::string expected_name = reg.format(expected.value);

  // A plain number where a brdf is expected: an albedo or a lobe without its 1/π.
  if (plain_value && named("brdf", expected.value)) return lambert_hint();
  // A reflectance alone where light is expected (an ambient term of the albedo, not of the light).
  std::optional<BaseId> energy = reg.find_base("energy");
  if (plain_value && energy && expected.value.exponent(*energy) != 0) {
    std::string reflectance;
    for (const ProductFactor& f : factors)
      if (reflectance.empty() && !f.literal && !f.name.empty() && f.dim.state == DimSlot::State::known && f.dim.value.is_dimensionless())
        reflectance = f.name;
    if (!reflectance.empty()) {
      std::string light;  // a variable in scope that is that light
      for (auto scope = scopes_.rbegin(); scope != scopes_.rend() && light.empty(); ++scope)
        for (const auto& [name, var] : *scope) {
          const DimSlot d = value_dimension(var.type, reg);
          if (!var.builtin && d.is_known() && d.value == expected.value && (light.empty() || name < light)) light = name;
        }
      return "'" + reflectance + "' is a plain number, a reflectance: the light it reflects is missing from the product" +
             (light.empty() ? ", a " + expected_name + " (or an irradiance times a brdf)" : ", e.g. " + light + " * " + reflectance);
    }
  }
  // A number written without its unit (2π(1 - cos θmax) for a cone's solid angle).
  if (plain_value && (all_plain || factors.empty()) && !is({{"angle", -1}}) && !is({{"proj", -1}})) {
    for (const Unit& unit : reg.units())
      if (unit.dimension == expected.value && DimensionRegistry::same_scale(unit.scale, 1.0))
        return "a plain number where " + expected_name + " is expected: give it its unit, e.g. x * " + unit.name;
    for (const Unit& unit : reg.units()) {
      Checked<Dimension> inverse = divide(Dimension{}, unit.dimension);
      if (inverse && *inverse == expected.value && DimensionRegistry::same_scale(unit.scale, 1.0))
        return "a plain number where " + expected_name + " (per " + unit.name + ") is expected: a density over " +
               reg.format(unit.dimension) + " is per unit of it, e.g. x / " + unit.name + " (a phase function is 1/(4π) per steradian)";
    }
  }
  // Irradiance where radiance is expected because a factor meant to be a brdf is a plain number.
  if (is({{"solid_angle", 1}, {"proj", 1}})) {
    std::vector<std::string> plain;
    for (const ProductFactor& f : factors)
      if (f.sign > 0 && !f.literal && !f.name.empty() && f.dim.state == DimSlot::State::known && f.dim.value.is_dimensionless())
        plain.push_back("'" + f.name + "'");
    if (plain.size() == 1)
      return "irradiance where radiance is expected, and " + plain[0] +
             " is a plain number: if it is the BRDF (a lobe), it needs its normalisation, 1/π per projected steradian: " +
             plain[0].substr(1, plain[0].size() - 2) + " * float<brdf>(1.0 / 3.14159265)";
    if (plain.size() > 1) {
      std::string names;
      for (std::size_t i = 0; i < plain.size(); ++i) names += (i == 0 ? "" : i + 1 == plain.size() ? " and " : ", ") + plain[i];
      return "irradiance where radiance is expected, and " + names +
             " are plain numbers: the one that is the BRDF (a lobe) needs its normalisation, 1/π per projected steradian: "
             "x * float<brdf>(1.0 / 3.14159265)";
    }
  }
  // A unit multiplied onto a value that already has it (innerConeDeg * degree).
  for (const ProductFactor& f : factors)
    if (f.unit && f.sign > 0 && f.dim.state == DimSlot::State::known && f.dim.value == r && !expected.value.is_dimensionless()) {
      for (const ProductFactor& g : factors)
        if (!g.unit && !g.name.empty() && g.dim.state == DimSlot::State::known && reg.reference(g.dim.value) &&
            *reg.reference(g.dim.value) == expected.value)
          return "'" + g.name + "' already is " + expected_name + ": multiplying it by the unit '" + f.name + "' gives " +
                 reg.format(found.value) + "; convert it instead, " + g.name + " in " + conversion_target(expected.value);
      return "the unit '" + f.name + "' multiplies a value that already is " + expected_name + "; convert with `in` instead";
    }
  // A unit of another dimension (5.0 * degree for a length).
  for (const ProductFactor& f : factors)
    if (f.unit && f.dim.state == DimSlot::State::known && f.dim.value == found.value) {
      for (const Unit& unit : reg.units())
        if (unit.dimension == expected.value)
          return "the unit '" + f.name + "' measures " + reg.format(found.value) + ", not " + expected_name + ": use a unit of " +
                 expected_name + ", e.g. x * " + unit.name;
    }
  if (is({{"proj", -1}})) {
    // The cosine is written, but one side of its dot product is not of unit length.
    if (std::string scaled = non_unit_dot_operand(expression_at(found_range)); !scaled.empty())
      return "the value lacks a factor of proj: the cosine's dot product takes " + scaled +
             ", which is not of unit length, so it is no cosine: normalize it";
    return "the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?";
  }
  if (is({{"proj", 1}})) {
    // One proj too many: a cosine applied twice, or a per-projected-area factor divided without its cosine.
    for (const ProductFactor& f : factors)
      if (f.sign < 0 && proj_of(f) < 0)
        return "the value has an extra factor of proj: '" + (f.name.empty() ? std::string("the divisor") : f.name) +
               "' is per projected area and divides without its cosine: missing the light-side cos θ of dω = cos θ dA / r²?";
    // A light's irradiance declared as it is measured, facing the light (a sun's E⊥): the
    // receiver's cosine then makes one proj too many, and the declaration is what is wrong.
    for (const ProductFactor& f : factors)
      if (f.sign > 0 && !f.name.empty() && f.dim.state == DimSlot::State::known && named("irradiance", f.dim.value))
        return "the value has an extra factor of proj: a cosine applied twice, or '" + f.name +
               "' is an irradiance measured facing its source (a sun's or a point light's), which is irradiance / proj: "
               "declared so, the receiver's cosine makes it the irradiance on the surface";
    return "the value has an extra factor of proj: is a cosine applied twice?";
  }
  bool pdf_factor = false;  // a density among the factors (pdf_area, pdf_solid_angle, ...)
  for (const ProductFactor& f : factors)
    if (f.dim.state == DimSlot::State::known && !f.literal)
      for (const char* pdf : {"pdf_solid_angle", "pdf_area", "pdf_projected_solid_angle"})
        if (named(pdf, f.dim.value)) pdf_factor = true;
  if (is({{"solid_angle", -1}})) return "the value lacks a factor of solid_angle: missing division by a pdf?";
  if (is({{"solid_angle", 1}})) {
    bool plain_divisor = false;  // Phi / (4.0 * PI): the 4π sr written as a number
    for (const ProductFactor& f : factors)
      plain_divisor = plain_divisor || (f.sign < 0 && f.dim.state == DimSlot::State::known && f.dim.value.is_dimensionless());
    if (!pdf_factor && plain_divisor)
      return "the value has an extra factor of solid_angle: a divisor that is a solid angle (4π over the sphere, a cone's "
             "2π(1 - cos θ)) is written as a plain number: give it its unit, x * steradian";
    return "the value has an extra factor of solid_angle: divided by a pdf twice, or multiplied where it should divide?";
  }
  if (is({{"solid_angle", -2}})) return "the value lacks solid_angle²: multiplied by a pdf where it should divide by it?";
  const bool area_per_sr = is({{"length", 2}, {"solid_angle", -1}}) || is({{"length", 2}, {"solid_angle", -1}, {"proj", -1}}) ||
                           is({{"length", 2}, {"solid_angle", -1}, {"proj", 1}});
  const bool sr_per_area = is({{"length", -2}, {"solid_angle", 1}}) || is({{"length", -2}, {"solid_angle", 1}, {"proj", 1}}) ||
                           is({{"length", -2}, {"solid_angle", 1}, {"proj", -1}});
  // Two densities of different measures met (an MIS weight mixing a light's area pdf with a BSDF's solid-angle pdf).
  if (named("pdf_solid_angle", expected.value) && named("pdf_area", found.value))
    return "a pdf per area where a pdf per solid angle is needed: convert it with the Jacobian, pdfA · r² / cos θ at the light";
  if (named("pdf_area", expected.value) && named("pdf_solid_angle", found.value))
    return "a pdf per solid angle where a pdf per area is needed: convert it with the Jacobian, pdfW · cos θ / r² at the light";
  if ((area_per_sr || sr_per_area) && !pdf_factor && !factors.empty()) {
    if (area_per_sr)
      for (const ProductFactor& f : factors)  // a point light's intensity used as the irradiance it gives
        if (f.sign > 0 && !f.name.empty() && f.dim.state == DimSlot::State::known && named("intensity", f.dim.value))
          return "the value lacks solid angle per area: '" + f.name +
                 "' is an intensity (power per steradian), missing the inverse-square falloff that makes it irradiance, inverse_square(d)?";
    return area_per_sr ? "the value lacks solid angle per area: missing the inverse-square falloff, inverse_square(d)?"
                       : "the value has an extra solid angle per area: the inverse-square falloff applied twice?";
  }
  if (area_per_sr) return "a pdf per area where a pdf per solid angle is needed (or the reverse): missing r²/cos Jacobian?";
  if (sr_per_area) return "a pdf per solid angle where a pdf per area is needed (or the reverse): missing r²/cos Jacobian?";
  if (is({{"solid_angle", -1}, {"proj", -1}})) {
    if (named("irradiance", expected.value))
      return "radiance where irradiance is expected: integrate over projected solid angle (× cos θ dω) to get irradiance";
    // One brdf too many: a BRDF applied to light that is already reflected (a cosine-convolved
    // irradiance probe holds E/π, which the albedo alone reflects).
    std::string brdf;
    for (const ProductFactor& f : factors)
      if (brdf.empty() && f.sign > 0 && !f.name.empty() && f.dim.state == DimSlot::State::known && named("brdf", f.dim.value))
        brdf = f.name;
    return brdf.empty() ? "the value has an extra factor of brdf (1/(solid_angle·proj)): a BRDF applied twice?"
                        : "the value has an extra factor of brdf (1/(solid_angle·proj)): '" + brdf +
                              "' is a brdf, applied here to radiance: a BRDF reflects irradiance (a cosine-convolved probe, E/π, "
                              "is reflected by the albedo alone)";
  }
  if (is({{"solid_angle", 1}, {"proj", 1}}))
    return "irradiance where radiance is expected: reflect it with a brdf (1/(solid_angle·proj)) to get radiance";
  // One length too many, from a cosine taken with a vector that was never normalized (N·L with L = lightPos - P).
  if (is({{"length", 1}}) || is({{"length", 1}, {"proj", -1}}))
    if (std::string scaled = non_unit_dot_operand(expression_at(found_range)); !scaled.empty())
      return "the value has an extra factor of length: the cosine's dot product takes " + scaled +
             ", which is not of unit length: normalize it";
  if (is({{"length", 2}})) return "the value has an extra factor of area: missing division by the squared distance?";
  // An area light's sample counted as a point light's: its radiance reaches a receiver through the solid angle
  // its area subtends, A cos θ_light / r², and the inverse square alone leaves A cos θ_light out.
  if (is({{"length", -2}, {"proj", -1}}))
    return "the value lacks a factor of area·proj: an area light's radiance needs the emitter's projected area, "
           "A · cos θ at the light (dω = A cos θ / r²)";
  if (is({{"length", -2}}))
    return "the value lacks a factor of area: a squared distance missing from the numerator (the r² of a Jacobian), or divided by twice?";
  if (is({{"angle", -1}}))
    return "a plain number where an angle is expected: radians or degrees? Use radians(x) or write the unit, x * degree";
  if (is({{"angle", 1}}) && expected.value.is_dimensionless())
    return "an angle where a plain number is expected: did you mean its sine or cosine, or degrees(x)?";
  if (plain_value) {
    for (const Unit& unit : reg.units())
      if (unit.dimension == expected.value)
        return "a plain number where " + expected_name + " is expected: give it a unit, e.g. x * " + unit.name;
    return "a plain number where " + expected_name + " is expected: convert it explicitly if it is one";
  }
  const std::string found_name = found.spelling.empty() ? reg.format(found.value) : found.spelling;
  if (expected.value.is_dimensionless()) return "the value has dimension " + found_name + " where a plain number is expected";
  auto simple = [&](const Dimension& d) { return d.factors().size() == 1 && d.factors()[0].exponent == 1; };
  if (simple(expected.value) && simple(found.value))
    return found_name + " where " + expected_name + " is expected: a different quantity, not a missing factor (another variable meant?)";
  // An extra light quantity by its name: two light quantities multiplied that should be added.
  if (energy && r.exponent(*energy) == 1 && expected.value.exponent(*energy) == 1)
    for (const DerivedDimension& d : reg.derived())
      if (d.value == r)
        return found_name + " where " + expected_name + " is expected: the value has an extra factor of " + d.name + " (" +
               reg.format_product(r) + "), a light quantity: two light quantities multiplied where they add?";
  return found_name + " where " + expected_name + " is expected: the value differs by a factor of " + reg.format_product(r);
}

// A unit direction plus a vector with a length (`V + toLight` for a half vector): normalize the vector first.
std::string Checker::unit_vector_sum_hint(const Value& lhs, const Value& rhs, const DimSlot& left, const DimSlot& right) const {
  auto unit = [](Geometry g) { return g == Geometry::direction || g == Geometry::normal; };
  const Geometry ga = lhs.type.geometry, gb = rhs.type.geometry;
  if ((unit(ga) && gb == Geometry::vector) || (ga == Geometry::vector && unit(gb))) {
    const Value& v = ga == Geometry::vector ? lhs : rhs;
    const DimSlot& d = ga == Geometry::vector ? left : right;
    if (d.state == DimSlot::State::known && !d.value.is_dimensionless()) {
      // Code only for a named vector: an expression has no name to write normalize() around.
      const std::string said = "a " + std::string(geometry_name(unit(ga) ? ga : gb)) + " has unit length, ";
      const std::string dimension = result_.registry.format(d.value);
      if (v.name.empty()) return said + "the other operand is a vector of dimension " + dimension + ": normalize it first";
      return said + "'" + v.name + "' is a vector of dimension " + dimension + ": normalize it first, normalize(" + v.name + ")";
    }
  }
  return operand_hint(left, right, rhs.range);
}

std::string Checker::lambert_hint() const {
  return "a plain number where a brdf is expected: an albedo or a lobe is a BRDF once normalised, 1/π per projected steradian "
         "(missing 1/π?): x * float<brdf>(1.0 / 3.14159265)";
}

// `a + b` and `a - b`: an albedo beside a brdf is the Lambert term without its 1/π whichever side it is on.
std::string Checker::operand_hint(const DimSlot& left, const DimSlot& right, SourceRange right_range) const {
  auto plain = [](const DimSlot& d) { return d.state == DimSlot::State::known && d.value.is_dimensionless(); };
  std::optional<Dimension> brdf = result_.registry.find_dimension("brdf");
  auto is_brdf = [&](const DimSlot& d) { return brdf && d.state == DimSlot::State::known && d.value == *brdf; };
  if ((plain(left) && is_brdf(right)) || (is_brdf(left) && plain(right))) return lambert_hint();
  return physics_hint(left, right, right_range);
}

// Why a value of one geometric kind does not fit where another is expected.
std::string Checker::kind_mismatch_hint(Geometry expected, Geometry found) const {
  if (expected == Geometry::direction && found == Geometry::vector) return "a vector becomes a direction only through normalize()";
  if (expected == Geometry::vector && found == Geometry::direction) return "a direction has unit length (normalize() drops the length): scale it by a length to get a vector";
  if (expected == Geometry::vector && found == Geometry::normal)
    return "a normal is not a vector: it transforms by the inverse transpose; convert explicitly with vector<S>(n) if you mean it";
  if (expected == Geometry::normal && found == Geometry::vector)
    return "transform the normal itself (a map applied to a normal uses the inverse transpose), or convert explicitly with normal<S>(v)";
  if (expected == Geometry::point && found == Geometry::hpoint) return "divide by w first: homogenize(h)";
  if (expected == Geometry::point && found == Geometry::vector) return "add it to a point to get a point";
  if (expected == Geometry::vector && found == Geometry::point) return "subtract another point to get a vector";
  if (expected == Geometry::normal && found == Geometry::direction)
    return "a direction is not a normal; convert explicitly with normal<S>(d) if it is one";
  if (expected == Geometry::direction && found == Geometry::normal)
    return "a normal is not a direction (a map carries it by the inverse transpose): take a normal<S> where one is meant, "
           "or convert explicitly with direction<S>(n)";
  if (expected == Geometry::map && found == Geometry::projmap) return "a projective map gives hpoints, not points";
  if (expected == Geometry::rigidmap && found == Geometry::map)
    return "a map composed with a non-rigid one is not rigid: declare it map<…> (normals then transform by the inverse transpose)";
  return {};
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
  d.with_note(Diagnostic::note(v.origin->range, v.origin->text + " as " + name_of(v.origin->type ? *v.origin->type : v.type)));
}

}  // namespace safegi::detail
