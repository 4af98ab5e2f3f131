#pragma once
// Unification in the Abelian group of dimensions, and of spaces.
//
// A dimension term is a constant dimension times integer powers of dimension
// variables (`D^2 * length`). An equation term = term is, for every base
// dimension, one linear equation over the variables' exponents of that base;
// all bases share the same coefficient matrix, so the system is solved once by
// exact rational Gauss-Jordan elimination with the bases as right-hand sides.
// Equations are added in order, so a conflict is reported at the first
// equation that contradicts the ones before it.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "safegi/dimension_algebra/dimension.hpp"
#include "safegi/dimension_algebra/registry.hpp"

namespace safegi {

using DimVarId = std::uint32_t;

struct DimTerm {
  Dimension constant;
  std::vector<std::pair<DimVarId, std::int32_t>> variables;  // product of var^exponent

  static DimTerm of(Dimension d) { return {std::move(d), {}}; }
  static DimTerm variable(DimVarId v, std::int32_t exponent = 1) { return {Dimension{}, {{v, exponent}}}; }
};

enum class UnifyStatus {
  solved,           // every variable has exactly one integer solution
  no_solution,      // equation `conflicting_equation` contradicts the earlier ones
  non_integer,      // `variable` is determined but needs a fractional exponent
  underdetermined,  // `variable` is not fixed by the equations
  overflow,         // exponent arithmetic left the representable range
};

struct VariableSolution {
  enum class State { determined, non_integer, free };
  State state = State::free;
  Dimension value;                       // when determined
  std::vector<RationalFactor> rational;  // when non_integer: the fractional exponents
};

struct UnifyResult {
  UnifyStatus status = UnifyStatus::solved;
  std::vector<VariableSolution> variables;  // indexed by DimVarId
  std::size_t conflicting_equation = 0;     // no_solution
  BaseId conflicting_base = 0;              // no_solution: a base whose exponents disagree
  DimVarId variable = 0;                    // non_integer / underdetermined

  bool ok() const { return status == UnifyStatus::solved; }
};

class DimensionUnifier {
 public:
  DimVarId add_variable(std::string name);
  std::size_t variable_count() const { return names_.size(); }
  const std::string& variable_name(DimVarId v) const { return names_.at(v); }

  // Returns the equation's index (as reported in UnifyResult::conflicting_equation).
  std::size_t add_equation(DimTerm lhs, DimTerm rhs);
  std::size_t equation_count() const { return equations_.size(); }

  UnifyResult solve() const;

  // A human-readable account of a failed result, in the registry's words.
  std::string explain(const UnifyResult& result, const DimensionRegistry& registry) const;

 private:
  std::vector<std::string> names_;
  std::vector<std::pair<DimTerm, DimTerm>> equations_;
};

// Plain equality unification of space terms: a term is a declared space or a variable.
struct SpaceTerm {
  enum class Kind { space, variable };
  Kind kind = Kind::space;
  std::uint32_t id = 0;
  static SpaceTerm space(SpaceId s) { return {Kind::space, s}; }
  static SpaceTerm variable(std::uint32_t v) { return {Kind::variable, v}; }
  friend bool operator==(const SpaceTerm&, const SpaceTerm&) = default;
};

class SpaceUnifier {
 public:
  std::uint32_t add_variable(std::string name);
  const std::string& variable_name(std::uint32_t v) const { return names_.at(v); }
  // False (and nothing changes) when the two terms resolve to different spaces.
  bool unify(SpaceTerm a, SpaceTerm b);
  // The space a term is bound to, if any.
  std::optional<SpaceId> resolve(SpaceTerm t) const;

 private:
  std::uint32_t find(std::uint32_t v) const;
  std::vector<std::string> names_;
  mutable std::vector<std::uint32_t> parent_;
  std::vector<std::optional<SpaceId>> bound_;  // valid at roots
};

}  // namespace safegi
