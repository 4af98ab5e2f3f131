// ray<S>: an origin and a unit direction in one space; r(t) is the point at distance t.
#pragma once

#include "safegi/typed/map.hpp"
#include "safegi/typed/space.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

template <class S>
struct basic_ray {
  using space_type = S;
  basic_point<S> o;
  basic_direction<S> d;

  constexpr basic_ray() = default;
  constexpr basic_ray(basic_point<S> origin, basic_direction<S> dir) : o(origin), d(dir) {}
  /// A ray of another space never converts; this only exists to say so in words.
  template <class S2, class Report = diagnose::conversion_between_spaces<diagnose::kind::ray, S2, S>>
    requires(!std::is_same_v<S2, S>)
  SAFEGI_MISTAKE basic_ray(const basic_ray<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a ray from one space into another by assignment: transform(m, r)");  // NOLINT

  /// The point at distance t along the ray.
  constexpr basic_point<S> operator()(quantity<dim::length> t) const { return o + d * t; }
};

template <space_type S>
using ray = basic_ray<mode_space<S>>;

/// A ray moves to another space by moving its origin and its direction.
template <class A, class B, class S>
diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>>
transform(const basic_map<A, B>&, const basic_ray<S>&);
template <class A, class B, class S>
  requires rules::same_space<A, S>
constexpr basic_ray<B> transform(const basic_map<A, B>& m, const basic_ray<S>& r) {
  return basic_ray<B>{m(r.o), m(r.d)};
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
