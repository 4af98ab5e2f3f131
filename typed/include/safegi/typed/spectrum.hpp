// spectrum<D>: an RGB triple with one dimension D for all three channels. It follows
// the quantity rules: + - == need equal dimensions, * / combine them (per channel
// with another spectrum, uniformly with a quantity).
#pragma once

#include <glm/vec3.hpp>
#include <glm/exponential.hpp>

#include "safegi/typed/quantity.hpp"
#include "safegi/typed/representation.hpp"
#include "safegi/typed/units.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

template <class D>
class basic_spectrum {
 public:
  using dimension_type = D;

  /// Black.
  constexpr basic_spectrum() = default;
  constexpr basic_spectrum(zero_t) {}  // NOLINT: implicit, zero has every dimension
  constexpr basic_spectrum(quantity<D> r, quantity<D> g, quantity<D> b) : rgb_(raw(r), raw(g), raw(b)) {}
  /// The same value in every channel.
  constexpr explicit basic_spectrum(quantity<D> grey) : rgb_(raw(grey)) {}
  constexpr basic_spectrum(detail::raw_tag, vec3_rep rgb) : rgb_(rgb) {}
  /// Converting between dimensions is always a mistake, declared to say so in words.
  template <class E, class Report = typename diagnose::report_if<!std::is_same_v<E, D>, diagnose::words_conversion_between_dimensions<E, D>>::type>
    requires(!std::is_same_v<E, D>)
  SAFEGI_MISTAKE basic_spectrum(const basic_spectrum<E>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a spectrum of one dimension into another");  // NOLINT

  [[nodiscard]] constexpr vec3_rep raw_value() const { return rgb_; }
  [[nodiscard]] constexpr quantity<D> r() const { return make_quantity<D, real>(rgb_.r); }
  [[nodiscard]] constexpr quantity<D> g() const { return make_quantity<D, real>(rgb_.g); }
  [[nodiscard]] constexpr quantity<D> b() const { return make_quantity<D, real>(rgb_.b); }
  [[nodiscard]] constexpr quantity<D> operator[](int channel) const { return make_quantity<D, real>(rgb_[channel]); }

  constexpr basic_spectrum operator-() const { return {detail::raw_tag{}, -rgb_}; }
  constexpr basic_spectrum& operator+=(basic_spectrum other) {
    rgb_ += other.raw_value();
    return *this;
  }
  constexpr basic_spectrum& operator-=(basic_spectrum other) {
    rgb_ -= other.raw_value();
    return *this;
  }
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::plus_assign, D, E>>::type
  operator+=(basic_spectrum<E>);
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::minus_assign, D, E>>::type
  operator-=(basic_spectrum<E>);
  /// Scaling by a dimensionless factor (a plain number or a dimensionless spectrum).
  template <class Q>
    requires arithmetic<Q> || std::is_same_v<Q, basic_spectrum<dim::dimensionless>>
  constexpr basic_spectrum& operator*=(Q factor) {
    if constexpr (arithmetic<Q>)
      rgb_ *= real(factor);
    else
      rgb_ *= factor.raw_value();
    return *this;
  }
  template <arithmetic U>
  constexpr basic_spectrum& operator/=(U divisor) {
    rgb_ /= real(divisor);
    return *this;
  }

 private:
  vec3_rep rgb_{real(0)};
};

template <dimension_type D>
using spectrum = basic_spectrum<mode_dimension<D>>;

template <class D>
struct raw_access<basic_spectrum<D>> {
  using raw_type = vec3_rep;
  static constexpr vec3_rep to(basic_spectrum<D> s) { return s.raw_value(); }
  static constexpr basic_spectrum<D> from(vec3_rep rgb) { return {detail::raw_tag{}, rgb}; }
};

template <dimension_type D, class E>
constexpr spectrum<D> dimension_cast(basic_spectrum<E> s) {
  return {detail::raw_tag{}, s.raw_value()};
}

template <class D>
constexpr basic_spectrum<D> operator+(basic_spectrum<D> a, basic_spectrum<D> b) {
  return {detail::raw_tag{}, a.raw_value() + b.raw_value()};
}
template <class D, class E>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator+(basic_spectrum<D>, basic_spectrum<E>);
template <class D>
constexpr basic_spectrum<D> operator-(basic_spectrum<D> a, basic_spectrum<D> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}
template <class D, class E>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator-(basic_spectrum<D>, basic_spectrum<E>);
template <class D>
constexpr bool operator==(basic_spectrum<D> a, basic_spectrum<D> b) {
  return a.raw_value() == b.raw_value();
}
template <class D, class E>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::equal, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator==(basic_spectrum<D>, basic_spectrum<E>);
template <class D, class E>
constexpr basic_spectrum<dim::product<D, E>> operator*(basic_spectrum<D> a, basic_spectrum<E> b) {
  return {detail::raw_tag{}, a.raw_value() * b.raw_value()};
}
template <class D, class E>
constexpr basic_spectrum<dim::quotient<D, E>> operator/(basic_spectrum<D> a, basic_spectrum<E> b) {
  return {detail::raw_tag{}, a.raw_value() / b.raw_value()};
}

namespace detail {
template <class Q>
using scalar_for = std::conditional_t<quantity_like<Q>, Q, real>;
template <class Q>
constexpr real scalar_value(Q q) {
  return real(raw(scalar_for<Q>(q)));
}
}  // namespace detail

template <class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr basic_spectrum<dim::product<D, dimension_of<detail::scalar_for<Q>>>> operator*(basic_spectrum<D> s, Q q) {
  return {detail::raw_tag{}, s.raw_value() * detail::scalar_value(q)};
}
template <class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr basic_spectrum<dim::product<D, dimension_of<detail::scalar_for<Q>>>> operator*(Q q, basic_spectrum<D> s) {
  return s * q;
}
template <class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr basic_spectrum<dim::quotient<D, dimension_of<detail::scalar_for<Q>>>> operator/(basic_spectrum<D> s, Q q) {
  return {detail::raw_tag{}, s.raw_value() / detail::scalar_value(q)};
}
template <class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr basic_spectrum<dim::quotient<dimension_of<detail::scalar_for<Q>>, D>> operator/(Q q, basic_spectrum<D> s) {
  return {detail::raw_tag{}, detail::scalar_value(q) / s.raw_value()};
}

/// A spectrum times or over a unit, like a number: spectrum<dim::dimensionless>(0.5f) * units::watt.
template <class D, class E>
constexpr basic_spectrum<dim::product<D, E>> operator*(basic_spectrum<D> s, basic_unit<E> u) {
  return {detail::raw_tag{}, s.raw_value() * real(u.factor)};
}
template <class D, class E>
constexpr basic_spectrum<dim::quotient<D, E>> operator/(basic_spectrum<D> s, basic_unit<E> u) {
  return {detail::raw_tag{}, s.raw_value() / real(u.factor)};
}

/// Rec. 709 luminance Y, in the spectrum's own dimension.
template <class D>
constexpr quantity<D> luminance(basic_spectrum<D> s) {
  const vec3_rep c = s.raw_value();
  return make_quantity<D, real>(real(0.2126) * c.r + real(0.7152) * c.g + real(0.0722) * c.b);
}
template <class D>
constexpr quantity<D> max_component(basic_spectrum<D> s) {
  const vec3_rep c = s.raw_value();
  return make_quantity<D, real>(c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b));
}
template <class D>
constexpr quantity<D> average(basic_spectrum<D> s) {
  const vec3_rep c = s.raw_value();
  return make_quantity<D, real>((c.r + c.g + c.b) / real(3));
}
template <class D>
constexpr bool is_black(basic_spectrum<D> s) {
  const vec3_rep c = s.raw_value();
  return c.r == real(0) && c.g == real(0) && c.b == real(0);
}
/// Per-channel exponential (Beer–Lambert transmittance): the exponent must be dimensionless.
template <class D>
  requires(!rules::dimensionless<D>)
diagnose::argument_is_not_dimensionless<diagnose::op::exp, in_words<D>> exp(basic_spectrum<D>);
template <class D>
  requires rules::dimensionless<D>
constexpr basic_spectrum<dim::dimensionless> exp(basic_spectrum<D> s) {
  return {detail::raw_tag{}, glm::exp(s.raw_value())};
}
/// Per-channel square root; every exponent of D must be even.
template <class D>
  requires(!rules::even_exponents<D>)
diagnose::sqrt_of_odd_exponent<in_words<D>> sqrt(basic_spectrum<D>);
template <class D>
  requires rules::even_exponents<D>
constexpr basic_spectrum<dim::root<D, 2>> sqrt(basic_spectrum<D> s) {
  return {detail::raw_tag{}, glm::sqrt(s.raw_value())};
}
template <class D, class E>
  requires(!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::lerp, in_words<D>, in_words<E>, ratio_in_words<D, E>>
lerp(basic_spectrum<D>, basic_spectrum<E>, real);
template <class D>
constexpr basic_spectrum<D> lerp(basic_spectrum<D> a, basic_spectrum<D> b, real t) {
  return {detail::raw_tag{}, (real(1) - t) * a.raw_value() + t * b.raw_value()};
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi

/// A spectrum has no numeric limits (the primary template would answer black): a
/// channel's are std::numeric_limits<quantity<D>>.
template <class D>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_spectrum<D>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::spectrum, safegi::in_words<D>> {};
