#include "safegi/dimension_algebra/registry.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

namespace safegi {
namespace {

std::string superscript(std::int64_t n) {
  static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  // The magnitude as unsigned so INT64_MIN is printed correctly, not negated into UB.
  std::uint64_t magnitude = n < 0 ? 0 - static_cast<std::uint64_t>(n) : static_cast<std::uint64_t>(n);
  std::string s = n < 0 ? "⁻" : "";
  for (char c : std::to_string(magnitude)) s += digits[c - '0'];
  return s;
}

std::string power_text(const std::string& name, std::int64_t e, Notation notation) {
  if (e == 1) return name;
  if (notation == Notation::ascii) return name + "^" + std::to_string(e);
  return name + superscript(e);
}

}  // namespace

bool DimensionRegistry::claim(const std::string& name, Kind kind) {
  std::size_t index = 0;
  switch (kind) {
    case Kind::base: index = bases_.size(); break;
    case Kind::derived: index = derived_.size(); break;
    case Kind::unit: index = units_.size(); break;
    case Kind::space: index = spaces_.size(); break;
  }
  return kinds_.emplace(name, std::pair{kind, index}).second;
}

std::optional<BaseId> DimensionRegistry::add_base(std::string name, BaseKind kind) {
  if (!claim(name, Kind::base)) return std::nullopt;
  bases_.push_back(std::move(name));
  ratio_bases_.push_back(kind == BaseKind::ratio);
  return static_cast<BaseId>(bases_.size() - 1);
}

bool DimensionRegistry::is_ratio_base(BaseId id) const {
  if (is_unit_factor(id)) return is_only_ratios(unit_of_factor(id).dimension);
  return id < ratio_bases_.size() && ratio_bases_[id];
}

bool DimensionRegistry::is_only_ratios(const Dimension& d) const {
  for (const Factor& f : d.factors())
    if (!is_ratio_base(f.base)) return false;
  return true;
}

bool DimensionRegistry::add_derived(std::string name, Dimension value) {
  if (!claim(name, Kind::derived)) return false;
  derived_.push_back({std::move(name), std::move(value)});
  return true;
}

bool DimensionRegistry::add_unit(std::string name, Dimension dimension, double scale) {
  if (!claim(name, Kind::unit)) return false;
  units_.push_back({std::move(name), std::move(dimension), scale});
  return true;
}

std::optional<SpaceId> DimensionRegistry::add_space(std::string name, bool eye, bool frame) {
  if (!claim(name, Kind::space)) return std::nullopt;
  spaces_.push_back(std::move(name));
  eye_spaces_.push_back(eye);
  frame_spaces_.push_back(frame);
  return static_cast<SpaceId>(spaces_.size() - 1);
}

std::optional<BaseId> DimensionRegistry::find_base(std::string_view name) const {
  auto it = kinds_.find(std::string(name));
  if (it == kinds_.end() || it->second.first != Kind::base) return std::nullopt;
  return static_cast<BaseId>(it->second.second);
}

const DerivedDimension* DimensionRegistry::find_derived(std::string_view name) const {
  auto it = kinds_.find(std::string(name));
  if (it == kinds_.end() || it->second.first != Kind::derived) return nullptr;
  return &derived_[it->second.second];
}

std::optional<Dimension> DimensionRegistry::find_dimension(std::string_view name) const {
  if (auto b = find_base(name)) return Dimension::base(*b);
  if (const DerivedDimension* d = find_derived(name)) return d->value;
  return std::nullopt;
}

const Unit* DimensionRegistry::find_unit(std::string_view name) const {
  auto it = kinds_.find(std::string(name));
  if (it == kinds_.end() || it->second.first != Kind::unit) return nullptr;
  return &units_[it->second.second];
}

std::optional<SpaceId> DimensionRegistry::find_space(std::string_view name) const {
  auto it = kinds_.find(std::string(name));
  if (it == kinds_.end() || it->second.first != Kind::space) return std::nullopt;
  return static_cast<SpaceId>(it->second.second);
}

std::optional<Dimension> DimensionRegistry::make(
    std::initializer_list<std::pair<std::string_view, std::int32_t>> terms) const {
  Dimension result;
  for (const auto& [name, exponent] : terms) {
    std::optional<Dimension> d = find_dimension(name);
    if (!d) return std::nullopt;
    Checked<Dimension> p = power(*d, exponent);
    if (!p) return std::nullopt;
    Checked<Dimension> m = multiply(result, *p);
    if (!m) return std::nullopt;
    result = *m;
  }
  return result;
}

std::string DimensionRegistry::format_number(double value) {
  char buffer[512];
  const double magnitude = std::fabs(value);
  const bool fixed = magnitude == 0.0 || (magnitude >= 1e-6 && magnitude < 1e9);
  auto [end, ec] = fixed ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                         : std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, ec == std::errc() ? end : buffer);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

bool DimensionRegistry::same_scale(double a, double b) {
  return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b));
}

Dimension DimensionRegistry::measured_in(const Unit& unit) const {
  if (same_scale(unit.scale, 1.0)) return unit.dimension;
  for (std::size_t i = 0; i < units_.size(); ++i)
    if (units_[i].dimension == unit.dimension && same_scale(units_[i].scale, unit.scale))
      return Dimension::base(kUnitBase + static_cast<BaseId>(i));
  return unit.dimension;  // not a unit of this registry
}

bool DimensionRegistry::has_unit_factors(const Dimension& d) const {
  for (const Factor& f : d.factors())
    if (f.base >= kUnitBase) return true;
  return false;
}

Checked<Dimension> DimensionRegistry::reference(const Dimension& d) const {
  Dimension out;
  for (const Factor& f : d.factors()) {
    Checked<Dimension> part = is_unit_factor(f.base) ? power(unit_of_factor(f.base).dimension, f.exponent)
                                                     : Checked<Dimension>(Dimension::base(f.base, f.exponent));
    if (!part) return part;
    Checked<Dimension> m = multiply(out, *part);
    if (!m) return m;
    out = *m;
  }
  return out;
}

double DimensionRegistry::scale(const Dimension& d) const {
  double s = 1.0;
  for (const Factor& f : d.factors())
    if (is_unit_factor(f.base)) s *= std::pow(unit_of_factor(f.base).scale, f.exponent);
  return s;
}

std::string DimensionRegistry::factor_name(BaseId id) const {
  if (id < bases_.size()) return bases_[id];
  if (is_unit_factor(id)) return unit_of_factor(id).name;
  return "?";
}

std::string DimensionRegistry::format_units(const Dimension& d, Notation notation) const {
  std::vector<RationalFactor> factors;
  for (const Factor& f : d.factors()) factors.push_back({f.base, f.exponent, 1});
  auto name = [&](BaseId id) {
    if (id < bases_.size())
      for (const Unit& u : units_)
        if (same_scale(u.scale, 1.0) && u.dimension == Dimension::base(id)) return u.name;
    return factor_name(id);
  };
  return format_factors(factors, notation, name);
}

std::string DimensionRegistry::format(const Dimension& d, Notation notation) const {
  if (has_unit_factors(d)) {
    Checked<Dimension> measured = reference(d);
    return (measured ? format(*measured, notation) : std::string("?")) + " in " + format_units(d, notation);
  }
  for (const DerivedDimension& derived : derived_)
    if (derived.value == d) return derived.name;
  return format_product(d, notation);
}

std::string DimensionRegistry::format_product(const Dimension& d, Notation notation) const {
  std::vector<RationalFactor> factors;
  for (const Factor& f : d.factors()) factors.push_back({f.base, f.exponent, 1});
  return format_rational(factors, notation);
}

std::string DimensionRegistry::format_si(const Dimension& d, Notation notation) const {
  if (has_unit_factors(d)) return format_units(d, notation);
  // SI symbols of the prelude's bases, in the order units are usually written.
  static const struct {
    const char* base;
    const char* symbol;
  } kSymbols[] = {{"energy", "J"}, {"length", "m"}, {"time", "s"}, {"angle", "rad"}, {"solid_angle", "sr"}};
  std::vector<std::pair<std::string, std::int64_t>> terms;  // symbol, exponent; in print order
  const std::int64_t energy = find_base("energy") ? d.exponent(*find_base("energy")) : 0;
  const std::int64_t time = find_base("time") ? d.exponent(*find_base("time")) : 0;
  // W = J·s⁻¹: as many watts as energy and inverse time have in common.
  std::int64_t watts = 0;
  if (energy > 0 && time < 0) watts = std::min(energy, -time);
  if (energy < 0 && time > 0) watts = -std::min(-energy, time);
  terms.emplace_back("W", watts);
  for (const auto& s : kSymbols) {
    const std::optional<BaseId> base = find_base(s.base);
    if (!base) continue;
    std::int64_t e = d.exponent(*base);
    if (*base == find_base("energy")) e -= watts;
    if (*base == find_base("time")) e += watts;
    terms.emplace_back(s.symbol, e);
  }
  for (const Factor& f : d.factors()) {
    const std::string& name = f.base < bases_.size() ? bases_[f.base] : "?";
    const bool named = name == "proj" || std::any_of(std::begin(kSymbols), std::end(kSymbols),
                                                     [&](const auto& s) { return name == s.base; });
    if (!named) terms.emplace_back(name, f.exponent);
  }
  std::string out;
  const char* separator = notation == Notation::ascii ? "*" : "·";
  for (const bool positive : {true, false})
    for (const auto& [symbol, e] : terms)
      if (e != 0 && (e > 0) == positive) out += (out.empty() ? "" : separator) + power_text(symbol, e, notation);
  return out.empty() ? "1" : out;
}

std::string DimensionRegistry::format_rational(const std::vector<RationalFactor>& factors,
                                               Notation notation) const {
  return format_factors(factors, notation, [this](BaseId id) { return factor_name(id); });
}

std::string DimensionRegistry::format_factors(const std::vector<RationalFactor>& factors, Notation notation,
                                              const std::function<std::string(BaseId)>& name_of) const {
  std::string out;
  const char* separator = notation == Notation::ascii ? "*" : "·";
  auto emit = [&](const RationalFactor& f) {
    if (!out.empty()) out += separator;
    const std::string name = name_of(f.base);
    if (f.denominator == 1) {
      out += power_text(name, f.numerator, notation);
    } else {
      out += name + "^(" + std::to_string(f.numerator) + "/" + std::to_string(f.denominator) + ")";
    }
  };
  for (const RationalFactor& f : factors)
    if (f.numerator > 0) emit(f);
  for (const RationalFactor& f : factors)
    if (f.numerator < 0) emit(f);
  return out.empty() ? "1" : out;
}

std::string DimensionRegistry::describe(const DimensionError& error) const {
  const std::string name = factor_name(error.base);
  switch (error.kind) {
    case DimensionErrorKind::exponent_overflow:
      return "exponent of '" + name + "' overflows (" + std::to_string(error.exponent) + " combined with " +
             std::to_string(error.operand) + " leaves the 32-bit range)";
    case DimensionErrorKind::not_a_root:
      return "exponent " + std::to_string(error.exponent) + " of '" + name + "' is not divisible by " +
             std::to_string(error.operand);
    case DimensionErrorKind::invalid_root:
      return "root of degree " + std::to_string(error.operand) + " is not defined";
  }
  return "invalid dimension";
}

DimensionRegistry DimensionRegistry::rendering_prelude() {
  // vocabulary.def, the list C++ and scene files take too; the build makes safegi/prelude.sgl
  // from it, the same names in the same order (typechecker/src/prelude_test.cpp checks it).
  DimensionRegistry r;
  auto derive = [&r](std::string name, std::initializer_list<std::int32_t> exponents) {
    std::vector<Factor> factors;
    BaseId base = 0;
    for (std::int32_t exponent : exponents) factors.push_back({base++, exponent});
    r.add_derived(std::move(name), *Dimension::from_factors(std::move(factors)));
  };
  auto unit = [&r](std::string name, std::string_view dimension, double scale) {
    r.add_unit(std::move(name), *r.find_dimension(dimension), scale);
  };
  auto alias = [&r](std::string name, std::string_view of) {
    const Unit* same = r.find_unit(of);
    r.add_unit(std::move(name), same->dimension, same->scale);
  };
#define VOCABULARY_BASE(name) r.add_base(#name);
#define VOCABULARY_RATIO_BASE(name) r.add_base(#name, BaseKind::ratio);
#define VOCABULARY_DIMENSION(name, length, time, energy, angle, solid_angle, proj, shader) \
  derive(#name, {length, time, energy, angle, solid_angle, proj});
#define VOCABULARY_SYNONYM(name, of) r.add_derived(#name, r.find_derived(#of)->value);
#define VOCABULARY_UNIT(name, symbol, dimension, scale) unit(#name, #dimension, scale);
#define VOCABULARY_UNIT_ALIAS(name, of) alias(#name, #of);
#include "safegi/typed/vocabulary.def"
  return r;
}

}  // namespace safegi
