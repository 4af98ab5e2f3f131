// frame<S, L>: an orthonormal shading frame (s, t, n) given in space S. to_local takes
// values of S into the local space L, where the normal is +z, so that cos_theta(w) is
// the projected-cosine factor; from_local goes back.
#pragma once

#include <cmath>

#include "safegi/typed/space.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

template <class S, class L>
class basic_frame {
 public:
  using space_type = S;
  using local_space = L;

  constexpr basic_frame() = default;
  /// s, t, n must be orthonormal and right-handed (s × t = n).
  constexpr basic_frame(basic_direction<S> s, basic_direction<S> t, basic_normal<S> n) : s_(s), t_(t), n_(n) {}

  /// A frame around n (Duff et al. 2017, "Building an orthonormal basis, revisited").
  static basic_frame from_normal(basic_normal<S> n) {
    const vec3_rep z = n.raw_value();
    const real sign = std::copysign(real(1), z.z);
    const real a = -real(1) / (sign + z.z);
    const real b = z.x * z.y * a;
    return {basic_direction<S>(real(1) + sign * z.x * z.x * a, sign * b, -sign * z.x),
            basic_direction<S>(b, sign + z.y * z.y * a, -z.y), n};
  }

  [[nodiscard]] constexpr basic_normal<S> normal() const { return n_; }
  [[nodiscard]] constexpr basic_direction<S> tangent() const { return s_; }
  [[nodiscard]] constexpr basic_direction<S> bitangent() const { return t_; }

  template <class S2>
  diagnose::space_mismatch<diagnose::op::to_local, S, S2> to_local(basic_direction<S2>) const;
  template <class S2>
    requires rules::same_space<S, S2>
  constexpr basic_direction<L> to_local(basic_direction<S2> w) const {
    return {detail::raw_tag{}, local(w.raw_value())};
  }
  template <class S2, class D>
  diagnose::space_mismatch<diagnose::op::to_local, S, S2> to_local(basic_vector<S2, D>) const;
  template <class S2, class D>
    requires rules::same_space<S, S2>
  constexpr basic_vector<L, D> to_local(basic_vector<S2, D> v) const {
    return {detail::raw_tag{}, local(v.raw_value())};
  }
  template <class S2>
  diagnose::space_mismatch<diagnose::op::to_local, S, S2> to_local(basic_normal<S2>) const;
  template <class S2>
    requires rules::same_space<S, S2>
  constexpr basic_normal<L> to_local(basic_normal<S2> n) const {  // orthonormal: same as directions
    return {detail::raw_tag{}, local(n.raw_value())};
  }
  template <class L2>
  diagnose::space_mismatch<diagnose::op::from_local, L, L2> from_local(basic_direction<L2>) const;
  template <class L2>
    requires rules::same_space<L, L2>
  constexpr basic_direction<S> from_local(basic_direction<L2> w) const {
    return {detail::raw_tag{}, global(w.raw_value())};
  }
  template <class L2, class D>
  diagnose::space_mismatch<diagnose::op::from_local, L, L2> from_local(basic_vector<L2, D>) const;
  template <class L2, class D>
    requires rules::same_space<L, L2>
  constexpr basic_vector<S, D> from_local(basic_vector<L2, D> v) const {
    return {detail::raw_tag{}, global(v.raw_value())};
  }
  template <class L2>
  diagnose::space_mismatch<diagnose::op::from_local, L, L2> from_local(basic_normal<L2>) const;
  template <class L2>
    requires rules::same_space<L, L2>
  constexpr basic_normal<S> from_local(basic_normal<L2> n) const {
    return {detail::raw_tag{}, global(n.raw_value())};
  }

 private:
  [[nodiscard]] constexpr vec3_rep local(vec3_rep v) const {
    return {glm::dot(v, s_.raw_value()), glm::dot(v, t_.raw_value()), glm::dot(v, n_.raw_value())};
  }
  [[nodiscard]] constexpr vec3_rep global(vec3_rep v) const {
    return v.x * s_.raw_value() + v.y * t_.raw_value() + v.z * n_.raw_value();
  }

  basic_direction<S> s_{real(1), real(0), real(0)};
  basic_direction<S> t_{real(0), real(1), real(0)};
  basic_normal<S> n_{real(0), real(0), real(1)};
};

template <space_type S, space_type L = spaces::shading>
using frame = basic_frame<mode_space<S>, mode_space<L>>;

/// cos θ of a direction in a shading space (normal = +z): the projected-cosine factor.
template <class L>
constexpr quantity<dim::proj> cos_theta(basic_direction<L> w) {
  return make_quantity<mode_dimension<dim::proj>, real>(w.z());
}
/// |cos θ|, for two-sided shading.
template <class L>
constexpr quantity<dim::proj> abs_cos_theta(basic_direction<L> w) {
  return make_quantity<mode_dimension<dim::proj>, real>(std::abs(w.z()));
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
