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

  /// The point at distance t along the ray.
  constexpr basic_point<S> operator()(quantity<dim::length> t) const { return o + d * t; }
};

template <space_type S>
using ray = basic_ray<mode_space<S>>;

/// A ray moves to another space by moving its origin and its direction.
template <class A, class B, class S>
constexpr basic_ray<B> transform(const basic_map<A, B>& m, const basic_ray<S>& r) {
  return {m(r.o), m(r.d)};
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
