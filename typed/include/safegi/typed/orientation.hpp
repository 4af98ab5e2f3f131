// Orientation, opt-in: which way a vector or direction points relative to the point being
// shaded, as the shader language's `away` / `toward` (docs/language.md, "Orientation").
//
//   sg::shaded_point<world> P = sg::shaded(p);            // the point being shaded
//   sg::oriented<sg::away, sg::vector<world>> to_light = light_pos - P;    // q - P: away
//   sg::oriented<sg::toward, sg::vector<world>> travel = P - light_pos;    // P - q: toward
//   auto wi = sg::normalize(to_light);                     // oriented<away, direction<world>>
//
// An oriented value is its value (it derives from it: dot, cross, maps and everything else
// take it as the plain kind, which forgets the orientation); -x flips it; normalize and
// a sum of two of one orientation keep it. Only a function that asks for an orientation
// checks it: a parameter oriented<away, direction<S>> refuses a toward one
// (diagnose::orientation_mismatch) and an unoriented one (diagnose::orientation_unknown),
// so a light that takes the direction from the lens to the light cannot be handed the
// light's travel direction. as_away(x) / as_toward(x) state an orientation (a sampled
// direction flipped into the normal's hemisphere is a new outgoing one), greppable.
//
// Unchecked, oriented<O, X> is X, shaded_point<S> is point<S>, and as_away(x) is x: the
// same source builds, to the same code.
#pragma once

#include <type_traits>

#include "safegi/typed/space.hpp"

namespace safegi {

/// Points from the shaded point outward (toward a light, the eye): pbrt's wi and wo.
struct away;
/// Points at the shaded point (an incident ray, a light's travel direction): GLSL's I.
struct toward;

namespace orientation_detail {
template <class O>
struct opposite_orientation;
template <>
struct opposite_orientation<away> {
  using type = toward;
};
template <>
struct opposite_orientation<toward> {
  using type = away;
};
}  // namespace orientation_detail
template <class O>
using opposite = typename orientation_detail::opposite_orientation<O>::type;

template <class O>
concept orientation_word = std::is_same_v<O, away> || std::is_same_v<O, toward>;

}  // namespace safegi

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// X (a vector or a direction) known to point O (away or toward) relative to the point
/// being shaded. Use the alias oriented<O, X>.
template <class O, class X>
class basic_oriented : public X {
  static_assert(orientation_word<O>, "oriented<O, X>: O is safegi::away or safegi::toward");

 public:
  using orientation = O;
  using value_type = X;

  constexpr basic_oriented(detail::raw_tag, X x) : X(x) {}
  /// The opposite orientation is a mistake, and so is a value without one.
  template <class O2, class Report = diagnose::orientation_mismatch<O2, O, X>>
    requires(!std::is_same_v<O2, O>)
  SAFEGI_MISTAKE basic_oriented(const basic_oriented<O2, X>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("the value points the other way relative to the shaded point: negate it (-w) if the other one was meant");  // NOLINT
  template <class Report = diagnose::orientation_unknown<O, X>>
  SAFEGI_MISTAKE basic_oriented(const X& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("this parameter needs an orientation: derive the value from the shaded point (q - shaded(p)) or state one, as_away(x) / as_toward(x)");  // NOLINT

  /// The value itself, its orientation forgotten (also an implicit conversion to X).
  [[nodiscard]] constexpr X value() const { return *this; }
  /// Flipped: -wi points toward the shaded point if wi points away from it.
  constexpr basic_oriented<opposite<O>, X> operator-() const {
    return {detail::raw_tag{}, X::operator-()};
  }
};

template <class O, class X>
using oriented = std::conditional_t<is_checked, basic_oriented<O, X>, X>;

/// raw(x) is the value's; from_raw<oriented<O, X>>(r) states an orientation, as as_away does.
template <class O, class X>
struct raw_access<basic_oriented<O, X>> {
  using raw_type = typename raw_access<X>::raw_type;
  static constexpr raw_type to(const basic_oriented<O, X>& x) { return raw_access<X>::to(x.value()); }
  static constexpr basic_oriented<O, X> from(raw_type value) { return {detail::raw_tag{}, raw_access<X>::from(value)}; }
};

/// The point being shaded (the shader language's point<S, shaded>): a difference of it and
/// another point is oriented. It is a point<S> everywhere else.
/// Cost, measured (GCC 12, -O2): the oriented values are free; a *named* shaded_point local
/// makes GCC reserve a larger stack frame than for the plain point (a sub/add of %rsp,
/// no other instruction differs); shaded(p) used in place, as in q - shaded(p), is free.
template <class S>
class basic_shaded_point : public basic_point<S> {
 public:
  constexpr explicit basic_shaded_point(basic_point<S> p) : basic_point<S>(detail::raw_tag{}, p.raw_value()) {}
};

template <space_type S>
using shaded_point = std::conditional_t<is_checked, basic_shaded_point<mode_space<S>>, point<S>>;

/// Marks p as the point being shaded.
template <class S>
constexpr auto shaded(basic_point<S> p) {
  if constexpr (is_checked)
    return basic_shaded_point<S>(p);
  else
    return p;
}

namespace detail {
template <class O, class X>
constexpr auto stated(X x) {
  if constexpr (is_checked)
    return basic_oriented<O, X>(raw_tag{}, x);
  else
    return x;
}
}  // namespace detail
/// States an orientation (greppable, like a cast): a value the types cannot follow.
template <class X>
constexpr auto as_away(X x) {
  return detail::stated<away>(x);
}
template <class X>
constexpr auto as_toward(X x) {
  return detail::stated<toward>(x);
}
/// The value without its orientation (the identity unchecked, and on plain values).
template <class X>
constexpr X unoriented(X x) {
  return x;
}
template <class O, class X>
constexpr X unoriented(basic_oriented<O, X> x) {
  return x.value();
}

// q - P is away from the shaded point P, P - q toward it; two shaded points give no orientation.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_point<S>, basic_shaded_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_oriented<away, detail::displacement<S>> operator-(basic_point<S> q, basic_shaded_point<S2> p) {
  return {detail::raw_tag{}, detail::displacement<S>(detail::raw_tag{}, q.raw_value() - p.raw_value())};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_shaded_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_oriented<toward, detail::displacement<S>> operator-(basic_shaded_point<S> p, basic_point<S2> q) {
  return {detail::raw_tag{}, detail::displacement<S>(detail::raw_tag{}, p.raw_value() - q.raw_value())};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_shaded_point<S>, basic_shaded_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr detail::displacement<S> operator-(basic_shaded_point<S> a, basic_shaded_point<S2> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}

/// normalize keeps the orientation.
template <class O, class S, class D>
constexpr basic_oriented<O, basic_direction<S>> normalize(basic_oriented<O, basic_vector<S, D>> v) {
  return {detail::raw_tag{}, basic_direction<S>(detail::raw_tag{}, glm::normalize(v.raw_value()))};
}
/// A sum of two values of one orientation keeps it (wo + wi is away, like both); of two
/// orientations it has none (the plain sum, through the values).
template <class O, class X, class Y>
constexpr auto operator+(basic_oriented<O, X> a, basic_oriented<O, Y> b)
    -> basic_oriented<O, decltype(a.value() + b.value())> {
  return {detail::raw_tag{}, a.value() + b.value()};
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
