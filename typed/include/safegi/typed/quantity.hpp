// quantity<D, T>: one T carrying the dimension D. Addition and comparison need equal
// dimensions, multiplication and division combine them. A dimensionless quantity is
// the plain number T itself, so it converts to and from float with no ceremony.
//
// Portable API (identical in the checked and the unchecked build): the alias
// quantity<D, T>, the operators, the free functions below called as safegi::f(...),
// raw / from_raw / dimension_cast, and safegi::zero.
#pragma once

#include <cmath>
#include <compare>
#include <concepts>
#include <limits>
#include <type_traits>

#include "safegi/typed/config.hpp"
#include "safegi/typed/diagnose.hpp"
#include "safegi/typed/dimension.hpp"

namespace safegi {

template <class T>
concept arithmetic = std::is_arithmetic_v<T>;

inline namespace SAFEGI_MODE_NAMESPACE {

/// D in the checked build; every dimension collapses to dimensionless in the unchecked build.
template <dimension_type D>
using mode_dimension = std::conditional_t<is_checked, D, dim::dimensionless>;

namespace detail {
struct raw_tag {
  explicit raw_tag() = default;
};
}  // namespace detail

/// Zero of every dimension: `quantity<dim::radiance> L = safegi::zero;`, `if (pdf > safegi::zero)`.
struct zero_t {
  template <std::floating_point F>
  constexpr operator F() const {  // NOLINT: implicit on purpose
    return F(0);
  }
};
inline constexpr zero_t zero{};

template <std::floating_point F>
constexpr bool operator==(F value, zero_t) {
  return value == F(0);
}
template <std::floating_point F>
constexpr std::partial_ordering operator<=>(F value, zero_t) {
  return value <=> F(0);
}

/// The checked representation behind quantity<D, T> for a dimension other than
/// dimensionless. Use the alias quantity<D, T> in code meant to build in both modes.
template <dimension_type D, std::floating_point T = real>
class basic_quantity {
  static_assert(!std::is_same_v<D, dim::dimensionless>, "a dimensionless quantity is the plain number T");

 public:
  using dimension_type = D;
  using rep = T;

  constexpr basic_quantity() = default;
  constexpr basic_quantity(zero_t) {}  // NOLINT: implicit, zero has every dimension
  constexpr basic_quantity(detail::raw_tag, T value) : value_(value) {}

  // Conversions that are always mistakes, declared so that the error names both sides
  // (diagnose.hpp); never called.
  template <class E, class Report = typename diagnose::report_if<!std::is_same_v<E, D>, diagnose::words_conversion_between_dimensions<E, D>>::type>
    requires(!std::is_same_v<E, D>)
  SAFEGI_MISTAKE basic_quantity(const basic_quantity<E, T>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a quantity of one dimension into another");  // NOLINT
  template <class E, std::floating_point U, class Report = diagnose::representation_mismatch<diagnose::op::conversion, U, T>>
    requires(!std::is_same_v<U, T>)
  SAFEGI_MISTAKE basic_quantity(const basic_quantity<E, U>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("float and double quantities do not mix: build it in safegi::real (real(2) * units::metre, 2.0f * units::metre in a float build), or convert with from_raw<quantity<D, T>>(T(raw(q)))");  // NOLINT
  template <arithmetic U, class Report = typename diagnose::report_if<arithmetic<U>, diagnose::words_plain_number_with_dimension<diagnose::op::conversion, D>>::type>
  SAFEGI_MISTAKE basic_quantity(const U& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a plain number has no dimension: give it a unit (2.0f * units::metre)");  // NOLINT

  /// The value in the reference unit of D. Prefer safegi::raw(q), which also works unchecked.
  [[nodiscard]] constexpr T raw_value() const { return value_; }

  constexpr basic_quantity operator-() const { return basic_quantity(detail::raw_tag{}, -value_); }
  constexpr basic_quantity operator+() const { return *this; }

  constexpr basic_quantity& operator+=(basic_quantity other) {
    value_ += other.raw_value();
    return *this;
  }
  constexpr basic_quantity& operator-=(basic_quantity other) {
    value_ -= other.raw_value();
    return *this;
  }
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::plus_assign, D, E>>::type
  operator+=(basic_quantity<E, T>);
  template <class E, class U>
    requires(!std::is_same_v<T, U>)
  diagnose::representation_mismatch<diagnose::op::plus_assign, T, U> operator+=(basic_quantity<E, U>);
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::minus_assign, D, E>>::type
  operator-=(basic_quantity<E, T>);
  template <class E, class U>
    requires(!std::is_same_v<T, U>)
  diagnose::representation_mismatch<diagnose::op::minus_assign, T, U> operator-=(basic_quantity<E, U>);
  template <arithmetic U>
  constexpr basic_quantity& operator*=(U factor) {
    value_ *= T(factor);
    return *this;
  }
  template <arithmetic U>
  constexpr basic_quantity& operator/=(U divisor) {
    value_ /= T(divisor);
    return *this;
  }

 private:
  T value_ = T(0);
};

namespace detail {
template <dimension_type D, class T>
struct checked_quantity {
  using type = basic_quantity<D, T>;
};
template <class T>
struct checked_quantity<dim::dimensionless, T> {
  using type = T;
};
}  // namespace detail

#if SAFEGI_TYPED_CHECKED
template <dimension_type D, std::floating_point T = real>
using quantity = typename detail::checked_quantity<D, T>::type;
#else
template <dimension_type D, std::floating_point T = real>
using quantity = T;
#endif

// ---- what a quantity-like value is: a basic_quantity or a plain floating-point number

template <class Q>
struct quantity_traits {};
template <std::floating_point T>
struct quantity_traits<T> {
  using dimension_type = dim::dimensionless;
  using rep = T;
};
template <class D, class T>
struct quantity_traits<basic_quantity<D, T>> {
  using dimension_type = D;
  using rep = T;
};

template <class Q>
concept quantity_like = requires { typename quantity_traits<Q>::dimension_type; };

template <quantity_like Q>
using dimension_of = typename quantity_traits<Q>::dimension_type;
template <quantity_like Q>
using rep_of = typename quantity_traits<Q>::rep;

/// Builds quantity<D, T> from a value in D's reference unit (internal building block).
template <dimension_type D, std::floating_point T>
constexpr quantity<D, T> make_quantity(T value) {
  if constexpr (std::is_same_v<quantity<D, T>, T>)
    return value;
  else
    return quantity<D, T>(detail::raw_tag{}, value);
}

// ---- leaving and entering the typed world: raw(x), from_raw<X>(r), dimension_cast<D>(x)

/// Specialised by every typed kind: raw_type, to(x), from(raw).
template <class X>
struct raw_access {};

template <std::floating_point T>
struct raw_access<T> {
  using raw_type = T;
  static constexpr T to(T value) { return value; }
  static constexpr T from(T value) { return value; }
};
template <class D, class T>
struct raw_access<basic_quantity<D, T>> {
  using raw_type = T;
  static constexpr T to(basic_quantity<D, T> q) { return q.raw_value(); }
  static constexpr basic_quantity<D, T> from(T value) { return {detail::raw_tag{}, value}; }
};

/// The plain representation of a typed value, in reference units (metre, second, ...).
template <class X>
constexpr auto raw(const X& x) -> decltype(raw_access<X>::to(x)) {
  return raw_access<X>::to(x);
}

/// A typed value from its plain representation, in reference units: from_raw<point<world>>(v).
template <class X>
constexpr X from_raw(typename raw_access<X>::raw_type value) {
  return raw_access<X>::from(value);
}

/// The explicit escape hatch: the same number, now claimed to have dimension D.
template <dimension_type D, quantity_like Q>
constexpr quantity<D, rep_of<Q>> dimension_cast(Q q) {
  return make_quantity<D, rep_of<Q>>(raw(q));
}

// ---- operators (only basic_quantity needs them; plain numbers have their own)

// Each operation on two quantities has its reports beside it (diagnose.hpp): the operation
// takes one dimension and one representation twice, so any other pair selects a report,
// which names the two sides; each report requires its rule to fail, so a valid call never
// forms one (diagnose.hpp, report_if).
template <class D, class T>
constexpr basic_quantity<D, T> operator+(basic_quantity<D, T> a, basic_quantity<D, T> b) {
  return {detail::raw_tag{}, a.raw_value() + b.raw_value()};
}
template <class D, class E, class T>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator+(basic_quantity<D, T>, basic_quantity<E, T>);
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::plus, T, U> operator+(basic_quantity<D, T>, basic_quantity<E, U>);
template <class D, class T>
constexpr basic_quantity<D, T> operator-(basic_quantity<D, T> a, basic_quantity<D, T> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}
template <class D, class E, class T>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator-(basic_quantity<D, T>, basic_quantity<E, T>);
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::minus, T, U> operator-(basic_quantity<D, T>, basic_quantity<E, U>);
template <class D, class T>
constexpr bool operator==(basic_quantity<D, T> a, basic_quantity<D, T> b) {
  return a.raw_value() == b.raw_value();
}
template <class D, class E, class T>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::equal, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator==(basic_quantity<D, T>, basic_quantity<E, T>);
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::equal, T, U> operator==(basic_quantity<D, T>, basic_quantity<E, U>);
template <class D, class T>
constexpr std::partial_ordering operator<=>(basic_quantity<D, T> a, basic_quantity<D, T> b) {
  return a.raw_value() <=> b.raw_value();
}
template <class D, class E, class T>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::compare, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator<=>(basic_quantity<D, T>, basic_quantity<E, T>);
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::compare, T, U> operator<=>(basic_quantity<D, T>, basic_quantity<E, U>);

template <class D, class T>
constexpr bool operator==(basic_quantity<D, T> a, zero_t) {
  return a.raw_value() == T(0);
}
template <class D, class T>
constexpr std::partial_ordering operator<=>(basic_quantity<D, T> a, zero_t) {
  return a.raw_value() <=> T(0);
}

// A plain number next to a dimensioned quantity in + - == < ... is a mistake; these
// overloads exist to say so in words (see diagnose.hpp).
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::plus, in_words<D>> operator+(basic_quantity<D, T>, U);
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::plus, in_words<D>> operator+(U, basic_quantity<D, T>);
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::minus, in_words<D>> operator-(basic_quantity<D, T>, U);
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::minus, in_words<D>> operator-(U, basic_quantity<D, T>);
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::equal, in_words<D>> operator==(basic_quantity<D, T>, U);
template <class D, class T, arithmetic U>
diagnose::plain_number_with_dimension<diagnose::op::compare, in_words<D>> operator<=>(basic_quantity<D, T>, U);

template <class D, class E, class T>
constexpr quantity<dim::product<D, E>, T> operator*(basic_quantity<D, T> a, basic_quantity<E, T> b) {
  return make_quantity<dim::product<D, E>, T>(a.raw_value() * b.raw_value());
}
template <class D, class E, class T>
constexpr quantity<dim::quotient<D, E>, T> operator/(basic_quantity<D, T> a, basic_quantity<E, T> b) {
  return make_quantity<dim::quotient<D, E>, T>(a.raw_value() / b.raw_value());
}
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::times, T, U> operator*(basic_quantity<D, T>, basic_quantity<E, U>);
template <class D, class E, class T, class U>
  requires(!std::is_same_v<T, U>)
diagnose::representation_mismatch<diagnose::op::divide, T, U> operator/(basic_quantity<D, T>, basic_quantity<E, U>);
template <class D, class T, arithmetic U>
constexpr basic_quantity<D, T> operator*(basic_quantity<D, T> a, U factor) {
  return {detail::raw_tag{}, a.raw_value() * T(factor)};
}
template <class D, class T, arithmetic U>
constexpr basic_quantity<D, T> operator*(U factor, basic_quantity<D, T> a) {
  return {detail::raw_tag{}, T(factor) * a.raw_value()};
}
template <class D, class T, arithmetic U>
constexpr basic_quantity<D, T> operator/(basic_quantity<D, T> a, U divisor) {
  return {detail::raw_tag{}, a.raw_value() / T(divisor)};
}
template <class D, class T, arithmetic U>
constexpr quantity<dim::inverse<D>, T> operator/(U numerator, basic_quantity<D, T> a) {
  return make_quantity<dim::inverse<D>, T>(T(numerator) / a.raw_value());
}

// ---- functions of quantities; each works on plain numbers too, so call them as
// safegi::sqrt(x) in code that must also build unchecked.

namespace detail {
template <quantity_like Q>
constexpr Q same_kind(rep_of<Q> value) {
  return make_quantity<dimension_of<Q>, rep_of<Q>>(value);
}
}  // namespace detail

template <quantity_like Q>
constexpr Q abs(Q q) {
  return detail::same_kind<Q>(std::abs(raw(q)));
}

template <quantity_like Q, quantity_like R>
  requires rules::same_dimension<dimension_of<Q>, dimension_of<R>>
constexpr Q min(Q a, R b) {
  return raw(b) < raw(a) ? detail::same_kind<Q>(raw(b)) : a;
}
template <quantity_like Q, quantity_like R>
  requires(!rules::same_dimension<dimension_of<Q>, dimension_of<R>>)
diagnose::dimension_mismatch<diagnose::op::min, in_words<dimension_of<Q>>, in_words<dimension_of<R>>,
                             ratio_in_words<dimension_of<Q>, dimension_of<R>>>
min(Q, R);
template <quantity_like Q, quantity_like R>
  requires rules::same_dimension<dimension_of<Q>, dimension_of<R>>
constexpr Q max(Q a, R b) {
  return raw(a) < raw(b) ? detail::same_kind<Q>(raw(b)) : a;
}
template <quantity_like Q, quantity_like R>
  requires(!rules::same_dimension<dimension_of<Q>, dimension_of<R>>)
diagnose::dimension_mismatch<diagnose::op::max, in_words<dimension_of<Q>>, in_words<dimension_of<R>>,
                             ratio_in_words<dimension_of<Q>, dimension_of<R>>>
max(Q, R);
/// max(x, safegi::zero), min(x, safegi::zero): zero has every dimension.
template <quantity_like Q>
constexpr Q max(Q a, zero_t) {
  return raw(a) < rep_of<Q>(0) ? Q(zero) : a;
}
template <quantity_like Q>
constexpr Q max(zero_t, Q b) {
  return safegi::max(b, zero);
}
template <quantity_like Q>
constexpr Q min(Q a, zero_t) {
  return rep_of<Q>(0) < raw(a) ? Q(zero) : a;
}
template <quantity_like Q>
constexpr Q min(zero_t, Q b) {
  return safegi::min(b, zero);
}
namespace detail {
/// The bound of clamp(q, low, high) whose dimension differs from q's (low, if both do).
template <class Q, class L, class H>
using clamp_bound_dimension =
    std::conditional_t<std::is_same_v<dimension_of<Q>, dimension_of<L>>, dimension_of<H>, dimension_of<L>>;
}  // namespace detail
template <quantity_like Q, quantity_like L, quantity_like H>
  requires(!rules::same_dimension<dimension_of<Q>, detail::clamp_bound_dimension<Q, L, H>>)
diagnose::dimension_mismatch<diagnose::op::clamp, in_words<dimension_of<Q>>,
                             in_words<detail::clamp_bound_dimension<Q, L, H>>,
                             ratio_in_words<dimension_of<Q>, detail::clamp_bound_dimension<Q, L, H>>>
clamp(Q, L, H);
template <quantity_like Q, quantity_like L, quantity_like H>
  requires rules::same_dimension<dimension_of<Q>, dimension_of<L>> &&
           rules::same_dimension<dimension_of<Q>, dimension_of<H>>
constexpr Q clamp(Q q, L low, H high) {
  return detail::same_kind<Q>(raw(q) < raw(low) ? raw(low) : (raw(high) < raw(q) ? raw(high) : raw(q)));
}
/// a + t (b - a), like std::lerp; t is a plain number.
template <quantity_like Q, quantity_like R>
  requires(!rules::same_dimension<dimension_of<Q>, dimension_of<R>>)
diagnose::dimension_mismatch<diagnose::op::lerp, in_words<dimension_of<Q>>, in_words<dimension_of<R>>,
                             ratio_in_words<dimension_of<Q>, dimension_of<R>>>
lerp(Q, R, rep_of<Q>);
template <quantity_like Q, quantity_like R>
  requires rules::same_dimension<dimension_of<Q>, dimension_of<R>>
constexpr Q lerp(Q a, R b, rep_of<Q> t) {
  return detail::same_kind<Q>((rep_of<Q>(1) - t) * raw(a) + t * raw(b));
}

template <quantity_like Q>
  requires(!rules::even_exponents<dimension_of<Q>>)
diagnose::sqrt_of_odd_exponent<in_words<dimension_of<Q>>> sqrt(Q);
template <quantity_like Q>
  requires rules::even_exponents<dimension_of<Q>>
constexpr quantity<dim::root<dimension_of<Q>, 2>, rep_of<Q>> sqrt(Q q) {
  return make_quantity<dim::root<dimension_of<Q>, 2>, rep_of<Q>>(std::sqrt(raw(q)));
}
/// sqrt(max(q, 0)): pbrt's SafeSqrt, for values that rounding can push below zero.
template <quantity_like Q>
  requires(!rules::even_exponents<dimension_of<Q>>)
diagnose::sqrt_of_odd_exponent<in_words<dimension_of<Q>>> safe_sqrt(Q);
template <quantity_like Q>
  requires rules::even_exponents<dimension_of<Q>>
constexpr quantity<dim::root<dimension_of<Q>, 2>, rep_of<Q>> safe_sqrt(Q q) {
  const rep_of<Q> value = raw(q);
  return make_quantity<dim::root<dimension_of<Q>, 2>, rep_of<Q>>(std::sqrt(value > 0 ? value : 0));
}

template <int N, quantity_like Q>
constexpr quantity<dim::pow<dimension_of<Q>, N>, rep_of<Q>> pow(Q q) {
  rep_of<Q> result(1);
  for (int i = 0; i < (N < 0 ? -N : N); ++i) result *= raw(q);
  return make_quantity<dim::pow<dimension_of<Q>, N>, rep_of<Q>>(N < 0 ? rep_of<Q>(1) / result : result);
}
/// A real exponent needs a dimensionless base.
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::pow, in_words<dimension_of<Q>>> pow(Q, rep_of<Q>);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr rep_of<Q> pow(Q base, rep_of<Q> exponent) {
  return std::pow(raw(base), exponent);
}

template <quantity_like Q>
  requires(!rules::angle<dimension_of<Q>>)
diagnose::argument_is_not_an_angle<diagnose::op::sin, in_words<dimension_of<Q>>> sin(Q);
template <quantity_like Q>
  requires rules::angle<dimension_of<Q>>
constexpr rep_of<Q> sin(Q angle) {
  return std::sin(raw(angle));
}
template <quantity_like Q>
  requires(!rules::angle<dimension_of<Q>>)
diagnose::argument_is_not_an_angle<diagnose::op::cos, in_words<dimension_of<Q>>> cos(Q);
template <quantity_like Q>
  requires rules::angle<dimension_of<Q>>
constexpr rep_of<Q> cos(Q angle) {
  return std::cos(raw(angle));
}
template <quantity_like Q>
  requires(!rules::angle<dimension_of<Q>>)
diagnose::argument_is_not_an_angle<diagnose::op::tan, in_words<dimension_of<Q>>> tan(Q);
template <quantity_like Q>
  requires rules::angle<dimension_of<Q>>
constexpr rep_of<Q> tan(Q angle) {
  return std::tan(raw(angle));
}
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::asin, in_words<dimension_of<Q>>> asin(Q);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr quantity<dim::angle, rep_of<Q>> asin(Q ratio) {
  return make_quantity<dim::angle, rep_of<Q>>(std::asin(raw(ratio)));
}
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::acos, in_words<dimension_of<Q>>> acos(Q);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr quantity<dim::angle, rep_of<Q>> acos(Q ratio) {
  return make_quantity<dim::angle, rep_of<Q>>(std::acos(raw(ratio)));
}
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::atan, in_words<dimension_of<Q>>> atan(Q);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr quantity<dim::angle, rep_of<Q>> atan(Q ratio) {
  return make_quantity<dim::angle, rep_of<Q>>(std::atan(raw(ratio)));
}
/// The angle of (x, y); x and y may have any dimension, but the same one.
template <quantity_like Q, quantity_like R>
  requires(!rules::same_dimension<dimension_of<Q>, dimension_of<R>>)
diagnose::dimension_mismatch<diagnose::op::atan2, in_words<dimension_of<Q>>, in_words<dimension_of<R>>,
                             ratio_in_words<dimension_of<Q>, dimension_of<R>>>
atan2(Q, R);
template <quantity_like Q, quantity_like R>
  requires rules::same_dimension<dimension_of<Q>, dimension_of<R>>
constexpr quantity<dim::angle, rep_of<Q>> atan2(Q y, R x) {
  return make_quantity<dim::angle, rep_of<Q>>(std::atan2(raw(y), raw(x)));
}
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::exp, in_words<dimension_of<Q>>> exp(Q);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr rep_of<Q> exp(Q exponent) {
  return std::exp(raw(exponent));
}
template <quantity_like Q>
  requires(!rules::dimensionless<dimension_of<Q>>)
diagnose::argument_is_not_dimensionless<diagnose::op::log, in_words<dimension_of<Q>>> log(Q);
template <quantity_like Q>
  requires rules::dimensionless<dimension_of<Q>>
constexpr rep_of<Q> log(Q argument) {
  return std::log(raw(argument));
}
template <quantity_like Q>
constexpr bool isfinite(Q q) {
  return std::isfinite(raw(q));
}
template <quantity_like Q>
constexpr bool isnan(Q q) {
  return std::isnan(raw(q));
}
template <quantity_like Q>
constexpr bool isinf(Q q) {
  return std::isinf(raw(q));
}
/// True for negative values, -0 and NaNs with the sign bit (std::signbit): any dimension.
template <quantity_like Q>
constexpr bool signbit(Q q) {
  return std::signbit(raw(q));
}

/// π as a plain number (an angle is `pi * units::radian`), in the representation's precision.
inline constexpr real pi = real(3.14159265358979323846);

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi

/// std::numeric_limits<quantity<D, T>>: T's limits, in D's reference unit.
/// Without it the primary template answers every question with T() (zero): a ray's
/// reach of std::numeric_limits<Length>::infinity() was 0 m, and every ray missed.
/// The unchecked build needs nothing here: its quantity<D, T> is T itself.
/// epsilon() and round_error() keep T's numbers too (1 + epsilon is a relative step;
/// in a dimension they are only what the type says: the same number, with the unit).
template <class D, class T>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_quantity<D, T>> : std::numeric_limits<T> {
 private:
  using Q = safegi::SAFEGI_MODE_NAMESPACE::basic_quantity<D, T>;
  using Limits = std::numeric_limits<T>;
  static constexpr Q of(T value) noexcept { return safegi::from_raw<Q>(value); }

 public:
  static constexpr Q min() noexcept { return of(Limits::min()); }
  static constexpr Q max() noexcept { return of(Limits::max()); }
  static constexpr Q lowest() noexcept { return of(Limits::lowest()); }
  static constexpr Q epsilon() noexcept { return of(Limits::epsilon()); }
  static constexpr Q round_error() noexcept { return of(Limits::round_error()); }
  static constexpr Q infinity() noexcept { return of(Limits::infinity()); }
  static constexpr Q quiet_NaN() noexcept { return of(Limits::quiet_NaN()); }
  static constexpr Q signaling_NaN() noexcept { return of(Limits::signaling_NaN()); }
  static constexpr Q denorm_min() noexcept { return of(Limits::denorm_min()); }
};
