// Units are constants of the right dimension. Every value is stored in one reference
// unit per dimension (SI: metre, second, joule, radian, steradian), converted once
// when it is built:  auto d = 5.0f * units::millimetre;   // holds 0.005 (metres)
// and leaving the typed world names the unit:           float mm = in(d, units::millimetre);
#pragma once

#include <type_traits>

#include "safegi/typed/quantity.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// How many reference units of D one of this unit is.
template <dimension_type D>
struct basic_unit {
  using dimension_type = D;
  double factor = 1.0;
};

template <dimension_type D>
using unit = basic_unit<mode_dimension<D>>;

template <class D, class E>
constexpr basic_unit<dim::product<D, E>> operator*(basic_unit<D> a, basic_unit<E> b) {
  return {a.factor * b.factor};
}
template <class D, class E>
constexpr basic_unit<dim::quotient<D, E>> operator/(basic_unit<D> a, basic_unit<E> b) {
  return {a.factor / b.factor};
}
template <int N, class D>
constexpr basic_unit<dim::pow<D, N>> pow(basic_unit<D> u) {
  double factor = 1.0;
  for (int i = 0; i < (N < 0 ? -N : N); ++i) factor *= u.factor;
  return {N < 0 ? 1.0 / factor : factor};
}

// A number (or quantity) times or over a unit: the dimensions combine and the value
// is converted to reference units, in the quantity's own precision.
template <class Q, class D>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(Q value, basic_unit<D> u) {
  using Value = std::conditional_t<quantity_like<Q>, Q, real>;
  using T = rep_of<Value>;
  return make_quantity<dim::product<dimension_of<Value>, D>, T>(T(raw(Value(value))) * T(u.factor));
}
template <class Q, class D>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator/(Q value, basic_unit<D> u) {
  using Value = std::conditional_t<quantity_like<Q>, Q, real>;
  using T = rep_of<Value>;
  return make_quantity<dim::quotient<dimension_of<Value>, D>, T>(T(raw(Value(value))) / T(u.factor));
}

/// The number of `u` in q — the greppable way out of the typed world.
template <quantity_like Q, class D>
  requires rules::same_dimension<dimension_of<Q>, D>
constexpr rep_of<Q> in(Q q, basic_unit<D> u) {
  return raw(q) / rep_of<Q>(u.factor);
}
template <quantity_like Q, class D>
  requires(!rules::same_dimension<dimension_of<Q>, D>)
diagnose::unit_of_another_dimension<in_words<dimension_of<Q>>, in_words<D>> in(Q, basic_unit<D>);

/// The vocabulary's units (vocabulary.def, the same as shaders' and scene files'), in
/// both spellings where there are two: units::meter and units::metre are one unit.
/// units::proj, the projected-cosine factor, has no physical unit; it makes radiance
/// writable: watt / (square_metre * steradian * proj).
namespace units {
#define VOCABULARY_UNIT(name, symbol, dimension, scale) inline constexpr unit<dim::dimension> name{scale};
#define VOCABULARY_UNIT_ALIAS(alias, of) inline constexpr auto alias = of;
#define VOCABULARY_CXX_UNIT(name, dimension, scale) inline constexpr unit<dim::dimension> name{scale};
#include "safegi/typed/vocabulary.def"
}  // namespace units

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
