// frame<S, L>: an orthonormal shading frame (s, t, n) given in space S. to_local takes
// values of S into the local space L, where the normal is +z, so that cos_theta(w) is
// the projected-cosine factor; from_local goes back.
//
// L is declared as one of two kinds of local space (space.hpp):
//   SAFEGI_NORMAL_FRAME_SPACE(name)   frames built from a normal alone (from_normal): the
//                                     azimuth is arbitrary (spaces::shading);
//   SAFEGI_TANGENT_FRAME_SPACE(name)  tangent frames (from_tangent(dpdu, n)): +x along
//                                     dp/du (spaces::tangent): normal maps, anisotropy.
// from_normal refuses a tangent space, so a frame of arbitrary azimuth never passes for a
// tangent frame; cos_theta and the other polar angles refuse a space that is no frame's
// (a world direction), and cos_phi / sin_phi (an absolute azimuth) want a tangent space.
#pragma once

#include <cmath>

#include "safegi/typed/space.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

template <class S, class L>
class basic_frame {
  static_assert(rules::frame_space<L>,
                "frame<S, L>: L must be a frame's local space, declared SAFEGI_NORMAL_FRAME_SPACE(name) (frames "
                "built by from_normal: arbitrary azimuth) or SAFEGI_TANGENT_FRAME_SPACE(name) (from_tangent: +x "
                "along dp/du)");

 public:
  using space_type = S;
  using local_space = L;

  constexpr basic_frame() = default;
  /// s, t, n must be orthonormal and right-handed (s × t = n).
  constexpr basic_frame(basic_direction<S> s, basic_direction<S> t, basic_normal<S> n) : s_(s), t_(t), n_(n) {}

  /// A frame around n (Duff et al. 2017, "Building an orthonormal basis, revisited"). Its
  /// azimuth is arbitrary, so L must be a normal-frame space (SAFEGI_NORMAL_FRAME_SPACE);
  /// a tangent space is refused (diagnose::azimuth_is_arbitrary): use from_tangent.
  template <class Local = L>
    requires rules::normal_frame_space<Local>
  static basic_frame from_normal(basic_normal<S> n) {
    const vec3_rep z = n.raw_value();
    const real sign = std::copysign(real(1), z.z);
    const real a = -real(1) / (sign + z.z);
    const real b = z.x * z.y * a;
    return {basic_direction<S>(real(1) + sign * z.x * z.x * a, sign * b, -sign * z.x),
            basic_direction<S>(b, sign + z.y * z.y * a, -z.y), n};
  }
  template <class Local = L>
  static diagnose::azimuth_is_arbitrary<diagnose::op::from_normal, Local> from_normal(basic_normal<S> n);

  /// A tangent frame: +z is n, +x is dp/du made orthogonal to n (Gram–Schmidt), +y is
  /// n × x. Any local space takes it (a tangent frame is also a frame around n). dpdu
  /// may have any dimension (a surface's dp/du is a length per parameter unit); it must
  /// not be parallel to n.
  template <class D>
  static basic_frame from_tangent(basic_vector<S, D> dpdu, basic_normal<S> n) {
    const vec3_rep z = n.raw_value();
    const vec3_rep x = glm::normalize(dpdu.raw_value() - glm::dot(dpdu.raw_value(), z) * z);
    return {basic_direction<S>(detail::raw_tag{}, x), basic_direction<S>(detail::raw_tag{}, glm::cross(z, x)), n};
  }
  static basic_frame from_tangent(basic_direction<S> dpdu, basic_normal<S> n) {
    return from_tangent(basic_vector<S, dim::dimensionless>(detail::raw_tag{}, dpdu.raw_value()), n);
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

// ---- polar and azimuthal angles of a direction in a frame's local space (normal = +z)
// Each takes only a frame space's direction; any other is a report naming the function
// and the space (diagnose::not_a_frame_space): cos_theta(w_world) read world z.

/// cos θ of a direction in a frame's local space: the projected-cosine factor.
template <class L>
diagnose::not_a_frame_space<diagnose::op::cos_theta, L> cos_theta(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
constexpr quantity<dim::proj> cos_theta(basic_direction<L> w) {
  return make_quantity<mode_dimension<dim::proj>, real>(w.z());
}
/// |cos θ|, for two-sided shading.
template <class L>
diagnose::not_a_frame_space<diagnose::op::abs_cos_theta, L> abs_cos_theta(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
constexpr quantity<dim::proj> abs_cos_theta(basic_direction<L> w) {
  return make_quantity<mode_dimension<dim::proj>, real>(std::abs(w.z()));
}
/// sin² θ = 1 - cos² θ (clamped at 0): a plain number, no projection.
template <class L>
diagnose::not_a_frame_space<diagnose::op::sin2_theta, L> sin2_theta(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
constexpr real sin2_theta(basic_direction<L> w) {
  const real s2 = real(1) - w.z() * w.z();
  return s2 > real(0) ? s2 : real(0);
}
/// sin θ: a plain number.
template <class L>
diagnose::not_a_frame_space<diagnose::op::sin_theta, L> sin_theta(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
inline real sin_theta(basic_direction<L> w) {
  return std::sqrt(sin2_theta(w));
}
namespace detail {
/// A cosine or sine computed as a ratio, kept in [-1, 1] against rounding.
constexpr real clamp_unit(real c) { return c < real(-1) ? real(-1) : (c > real(1) ? real(1) : c); }
/// cos φ (component x) or sin φ (component y) of w: that component over sin θ, `at_pole` where sin θ = 0.
template <class L>
inline real azimuth_component(basic_direction<L> w, real component, real at_pole) {
  const real s = sin_theta(w);
  return s > real(0) ? clamp_unit(component / s) : at_pole;
}
}  // namespace detail
/// cos(φa - φb) of two directions of one frame: independent of the frame's azimuth, so
/// any frame space takes it (Oren–Nayar's term).
template <class L, class L2>
diagnose::space_mismatch<diagnose::op::cos_delta_phi, L, L2> cos_delta_phi(basic_direction<L>, basic_direction<L2>);
template <class L, class L2>
  requires rules::same_space<L, L2>
diagnose::not_a_frame_space<diagnose::op::cos_delta_phi, L> cos_delta_phi(basic_direction<L>, basic_direction<L2>);
template <class L, class L2>
  requires rules::same_space<L, L2> && rules::frame_space<L>
inline real cos_delta_phi(basic_direction<L> a, basic_direction<L2> b) {
  const real xy = (a.x() * a.x() + a.y() * a.y()) * (b.x() * b.x() + b.y() * b.y());
  if (!(xy > real(0))) return real(1);
  return detail::clamp_unit((a.x() * b.x() + a.y() * b.y()) / std::sqrt(xy));
}
/// cos φ and sin φ, the azimuth from the tangent (dp/du): only in a tangent frame's space.
/// In a frame built from a normal alone the azimuth is arbitrary
/// (diagnose::azimuth_is_arbitrary); compare two azimuths with cos_delta_phi instead.
template <class L>
diagnose::not_a_frame_space<diagnose::op::cos_phi, L> cos_phi(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
diagnose::azimuth_is_arbitrary<diagnose::op::cos_phi, L> cos_phi(basic_direction<L>);
template <class L>
  requires rules::frame_space<L> && rules::tangent_frame_space<L>
inline real cos_phi(basic_direction<L> w) {
  return detail::azimuth_component(w, w.x(), real(1));
}
template <class L>
diagnose::not_a_frame_space<diagnose::op::sin_phi, L> sin_phi(basic_direction<L>);
template <class L>
  requires rules::frame_space<L>
diagnose::azimuth_is_arbitrary<diagnose::op::sin_phi, L> sin_phi(basic_direction<L>);
template <class L>
  requires rules::frame_space<L> && rules::tangent_frame_space<L>
inline real sin_phi(basic_direction<L> w) {
  return detail::azimuth_component(w, w.y(), real(0));
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
