#include "safegi/dimension_algebra/unifier.hpp"

#include <algorithm>
#include <numeric>

namespace safegi {
namespace {

struct Overflow {};

__extension__ typedef __int128 Wide;  // products of two int64 parts never overflow it

// Exact rational with int64 parts; every operation checks for overflow.
struct Rational {
  std::int64_t num = 0;
  std::int64_t den = 1;

  static Rational make(Wide n, Wide d) {
    if (d < 0) {
      n = -n;
      d = -d;
    }
    Wide a = n < 0 ? -n : n, b = d;
    while (b != 0) {
      Wide t = a % b;
      a = b;
      b = t;
    }
    if (a > 1) {
      n /= a;
      d /= a;
    }
    if (n > INT64_MAX || n < -INT64_MAX || d > INT64_MAX) throw Overflow{};
    return {static_cast<std::int64_t>(n), static_cast<std::int64_t>(d)};
  }
  bool zero() const { return num == 0; }
  friend Rational operator-(Rational a, Rational b) {
    return make(Wide{a.num} * b.den - Wide{b.num} * a.den, Wide{a.den} * b.den);
  }
  friend Rational operator*(Rational a, Rational b) {
    return make(Wide{a.num} * b.num, Wide{a.den} * b.den);
  }
  friend Rational operator/(Rational a, Rational b) {
    return make(Wide{a.num} * b.den, Wide{a.den} * b.num);
  }
};

struct Row {
  std::vector<Rational> coefficients;  // one per variable
  std::vector<Rational> rhs;           // one per base column
  std::size_t pivot = 0;

  void subtract(Rational factor, const Row& other) {
    if (factor.zero()) return;
    for (std::size_t i = 0; i < coefficients.size(); ++i)
      if (!other.coefficients[i].zero()) coefficients[i] = coefficients[i] - factor * other.coefficients[i];
    for (std::size_t i = 0; i < rhs.size(); ++i)
      if (!other.rhs[i].zero()) rhs[i] = rhs[i] - factor * other.rhs[i];
  }
};

}  // namespace

DimVarId DimensionUnifier::add_variable(std::string name) {
  names_.push_back(std::move(name));
  return static_cast<DimVarId>(names_.size() - 1);
}

std::size_t DimensionUnifier::add_equation(DimTerm lhs, DimTerm rhs) {
  equations_.emplace_back(std::move(lhs), std::move(rhs));
  return equations_.size() - 1;
}

UnifyResult DimensionUnifier::solve() const {
  UnifyResult result;
  const std::size_t n = names_.size();
  result.variables.resize(n);

  std::vector<BaseId> bases;  // the right-hand-side columns
  for (const auto& [lhs, rhs] : equations_)
    for (const DimTerm* t : {&lhs, &rhs})
      for (const Factor& f : t->constant.factors()) bases.push_back(f.base);
  std::sort(bases.begin(), bases.end());
  bases.erase(std::unique(bases.begin(), bases.end()), bases.end());
  auto column = [&](BaseId b) { return static_cast<std::size_t>(std::lower_bound(bases.begin(), bases.end(), b) - bases.begin()); };

  std::vector<Row> pivots;
  try {
    for (std::size_t e = 0; e < equations_.size(); ++e) {
      const auto& [lhs, rhs] = equations_[e];
      // lhs = rhs  ⇔  Σ (lhs_k - rhs_k)·X_k = rhs.constant - lhs.constant
      Row row{std::vector<Rational>(n), std::vector<Rational>(bases.size()), 0};
      for (const auto& [v, k] : lhs.variables) row.coefficients.at(v) = row.coefficients[v] - Rational{-k, 1};
      for (const auto& [v, k] : rhs.variables) row.coefficients.at(v) = row.coefficients[v] - Rational{k, 1};
      for (const Factor& f : rhs.constant.factors()) row.rhs[column(f.base)] = row.rhs[column(f.base)] - Rational{-f.exponent, 1};
      for (const Factor& f : lhs.constant.factors()) row.rhs[column(f.base)] = row.rhs[column(f.base)] - Rational{f.exponent, 1};

      for (const Row& p : pivots) row.subtract(row.coefficients[p.pivot], p);
      auto lead = std::find_if(row.coefficients.begin(), row.coefficients.end(), [](Rational q) { return !q.zero(); });
      if (lead == row.coefficients.end()) {
        auto bad = std::find_if(row.rhs.begin(), row.rhs.end(), [](Rational q) { return !q.zero(); });
        if (bad != row.rhs.end()) {
          result.status = UnifyStatus::no_solution;
          result.conflicting_equation = e;
          result.conflicting_base = bases[static_cast<std::size_t>(bad - row.rhs.begin())];
          return result;
        }
        continue;  // implied by the earlier equations
      }
      row.pivot = static_cast<std::size_t>(lead - row.coefficients.begin());
      const Rational scale = row.coefficients[row.pivot];
      for (Rational& q : row.coefficients) q = q / scale;
      for (Rational& q : row.rhs) q = q / scale;
      for (Row& p : pivots) p.subtract(p.coefficients[row.pivot], row);
      pivots.push_back(std::move(row));
    }
  } catch (const Overflow&) {
    result.status = UnifyStatus::overflow;
    return result;
  }

  std::optional<DimVarId> first_fractional, first_free;
  for (const Row& p : pivots) {
    bool depends_on_free = false;
    for (std::size_t i = 0; i < n; ++i)
      if (i != p.pivot && !p.coefficients[i].zero()) depends_on_free = true;
    if (depends_on_free) continue;
    VariableSolution& s = result.variables[p.pivot];
    std::vector<Factor> factors;
    bool integral = true, in_range = true;
    for (std::size_t c = 0; c < bases.size(); ++c) {
      const Rational q = p.rhs[c];
      if (q.zero()) continue;
      s.rational.push_back({bases[c], q.num, q.den});
      if (q.den != 1) integral = false;
      else if (q.num > INT32_MAX || q.num < INT32_MIN) in_range = false;
      else factors.push_back({bases[c], static_cast<std::int32_t>(q.num)});
    }
    if (!in_range) {
      result.status = UnifyStatus::overflow;
      result.variable = static_cast<DimVarId>(p.pivot);
      return result;
    }
    if (integral) {
      s.state = VariableSolution::State::determined;
      s.value = *Dimension::from_factors(std::move(factors));
      s.rational.clear();
    } else {
      s.state = VariableSolution::State::non_integer;
    }
  }
  for (DimVarId v = 0; v < n; ++v) {
    const VariableSolution::State state = result.variables[v].state;
    if (state == VariableSolution::State::non_integer && !first_fractional) first_fractional = v;
    if (state == VariableSolution::State::free && !first_free) first_free = v;
  }
  if (first_fractional) {
    result.status = UnifyStatus::non_integer;
    result.variable = *first_fractional;
  } else if (first_free) {
    result.status = UnifyStatus::underdetermined;
    result.variable = *first_free;
  }
  return result;
}

std::string DimensionUnifier::explain(const UnifyResult& result, const DimensionRegistry& registry) const {
  switch (result.status) {
    case UnifyStatus::solved: {
      std::string out;
      for (DimVarId v = 0; v < names_.size(); ++v) {
        if (!out.empty()) out += ", ";
        out += names_[v] + " = " + registry.format(result.variables[v].value);
      }
      return out;
    }
    case UnifyStatus::no_solution:
      return "constraint " + std::to_string(result.conflicting_equation + 1) +
             " contradicts the earlier ones (the exponents of '" + registry.factor_name(result.conflicting_base) +
             "' disagree)";
    case UnifyStatus::non_integer:
      return names_[result.variable] + " would be " +
             registry.format_rational(result.variables[result.variable].rational) +
             ", which is not a dimension (exponents must be integers)";
    case UnifyStatus::underdetermined:
      return names_[result.variable] + " is not determined by the arguments";
    case UnifyStatus::overflow:
      return "exponent arithmetic overflows";
  }
  return {};
}

std::uint32_t SpaceUnifier::add_variable(std::string name) {
  names_.push_back(std::move(name));
  parent_.push_back(static_cast<std::uint32_t>(parent_.size()));
  bound_.emplace_back();
  return parent_.back();
}

std::uint32_t SpaceUnifier::find(std::uint32_t v) const {
  while (parent_[v] != v) {
    parent_[v] = parent_[parent_[v]];
    v = parent_[v];
  }
  return v;
}

std::optional<SpaceId> SpaceUnifier::resolve(SpaceTerm t) const {
  if (t.kind == SpaceTerm::Kind::space) return t.id;
  return bound_[find(t.id)];
}

bool SpaceUnifier::unify(SpaceTerm a, SpaceTerm b) {
  std::optional<SpaceId> sa = resolve(a), sb = resolve(b);
  if (sa && sb) return *sa == *sb;
  if (a.kind == SpaceTerm::Kind::variable && b.kind == SpaceTerm::Kind::variable) {
    std::uint32_t ra = find(a.id), rb = find(b.id);
    if (ra != rb) {
      parent_[ra] = rb;
      if (!bound_[rb]) bound_[rb] = bound_[ra];
    }
    return true;
  }
  const SpaceTerm& var = a.kind == SpaceTerm::Kind::variable ? a : b;
  const SpaceId space = a.kind == SpaceTerm::Kind::variable ? *sb : *sa;
  bound_[find(var.id)] = space;
  return true;
}

}  // namespace safegi
