// map<A, B>: an affine transformation taking values in space A to space B, wrapping a
// GLM matrix by composition. Its inverse is stored beside it (as in pbrt-v4), so
// inverse() is free and normals, which transform by the inverse transpose, cost no
// inversion either. Name maps after the spaces they connect: worldFromObject.
//
// projective_map<A, B> is a projective transformation (a perspective camera): applied
// to a point it gives an hpoint<B>, never a point, so the divide by w stays explicit.
#pragma once

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "safegi/typed/space.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// The matrix and its inverse; the part both kinds of map share.
struct matrix_pair {
  mat4_rep forward{real(1)};
  mat4_rep inverse{real(1)};
};

/// outer ∘ inner: inner applies first.
inline matrix_pair compose(const matrix_pair& outer, const matrix_pair& inner) {
  return {outer.forward * inner.forward, inner.inverse * outer.inverse};
}

template <class A, class B>
class basic_map {
 public:
  using from_space = A;
  using to_space = B;

  /// The identity.
  constexpr basic_map() = default;
  constexpr basic_map(detail::raw_tag, matrix_pair m) : m_(m) {}
  /// A map between other spaces never converts; declared to say so in words.
  template <class A2, class B2, class Report = diagnose::map_conversion<diagnose::given<diagnose::map<A2, B2>>, diagnose::wanted<diagnose::map<A, B>>>>
    requires(!std::is_same_v<A2, A> || !std::is_same_v<B2, B>)
  SAFEGI_MISTAKE basic_map(const basic_map<A2, B2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a map<A, B> is never a map between other spaces; inverse(m) turns map<A, B> into map<B, A>");  // NOLINT

  [[nodiscard]] constexpr const matrix_pair& raw_value() const { return m_; }

  static basic_map translation(basic_vector<B, detail::length_dimension> offset) {
    return from_matrix(glm::translate(mat4_rep(real(1)), offset.raw_value()));
  }
  static basic_map scaling(real sx, real sy, real sz) {
    return {detail::raw_tag{},
            {glm::scale(mat4_rep(real(1)), vec3_rep(sx, sy, sz)),
             glm::scale(mat4_rep(real(1)), vec3_rep(real(1) / sx, real(1) / sy, real(1) / sz))}};
  }
  /// A rotation by `angle` about `axis` (right-handed).
  static basic_map rotation(quantity<dim::angle> angle, basic_direction<A> axis) {
    const mat4_rep r = glm::rotate(mat4_rep(real(1)), real(raw(angle)), axis.raw_value());
    return {detail::raw_tag{}, {r, glm::transpose(r)}};
  }
  /// A camera at `eye` looking at `target`; camera space as glm::lookAt (looking down -z).
  template <class W>
  static diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<W>>
  look_at(basic_point<W>, basic_point<W>, basic_direction<W>);
  template <class W>
    requires rules::same_space<A, W>
  static basic_map look_at(basic_point<W> eye, basic_point<W> target, basic_direction<W> up) {
    const mat4_rep view = glm::lookAt(eye.raw_value(), target.raw_value(), up.raw_value());
    return {detail::raw_tag{}, {view, glm::inverse(view)}};
  }
  /// Any invertible affine matrix (the inverse is computed once here).
  static basic_map from_matrix(const mat4_rep& m) { return {detail::raw_tag{}, {m, glm::inverse(m)}}; }

  // Application: each kind transforms as what it is.
  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>> operator()(basic_point<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_point<B> operator()(basic_point<S> p) const {
    return {detail::raw_tag{}, vec3_rep(m_.forward * vec4_rep(p.raw_value(), real(1)))};
  }
  template <class S, class D>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>>
  operator()(basic_vector<S, D>) const;
  template <class S, class D>
    requires rules::same_space<A, S>
  constexpr basic_vector<B, D> operator()(basic_vector<S, D> v) const {
    return {detail::raw_tag{}, mat3_rep(m_.forward) * v.raw_value()};
  }
  /// Directions stay unit length (renormalised after non-rigid maps).
  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>>
  operator()(basic_direction<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_direction<B> operator()(basic_direction<S> d) const {
    return {detail::raw_tag{}, glm::normalize(mat3_rep(m_.forward) * d.raw_value())};
  }
  /// Normals transform by the inverse transpose, then are renormalised.
  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>> operator()(basic_normal<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_normal<B> operator()(basic_normal<S> n) const {
    return {detail::raw_tag{}, glm::normalize(glm::transpose(mat3_rep(m_.inverse)) * n.raw_value())};
  }
  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>> operator()(basic_hpoint<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_hpoint<B> operator()(basic_hpoint<S> h) const {
    return {detail::raw_tag{}, m_.forward * h.raw_value()};
  }

 private:
  matrix_pair m_;
};

template <class A, class B>
class basic_projective_map {
 public:
  using from_space = A;
  using to_space = B;

  constexpr basic_projective_map() = default;
  constexpr basic_projective_map(detail::raw_tag, matrix_pair m) : m_(m) {}
  [[nodiscard]] constexpr const matrix_pair& raw_value() const { return m_; }

  /// An OpenGL-style perspective projection (glm::perspective).
  static basic_projective_map perspective(quantity<dim::angle> fov_y, real aspect, quantity<dim::length> near,
                                          quantity<dim::length> far) {
    const mat4_rep p = glm::perspective(real(raw(fov_y)), aspect, real(raw(near)), real(raw(far)));
    return {detail::raw_tag{}, {p, glm::inverse(p)}};
  }
  static basic_projective_map from_matrix(const mat4_rep& m) { return {detail::raw_tag{}, {m, glm::inverse(m)}}; }

  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>> operator()(basic_point<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_hpoint<B> operator()(basic_point<S> p) const {
    return {detail::raw_tag{}, m_.forward * vec4_rep(p.raw_value(), real(1))};
  }
  template <class S>
  diagnose::map_applied_to_wrong_space<diagnose::map<A, B>, diagnose::argument_in<S>> operator()(basic_hpoint<S>) const;
  template <class S>
    requires rules::same_space<A, S>
  constexpr basic_hpoint<B> operator()(basic_hpoint<S> h) const {
    return {detail::raw_tag{}, m_.forward * h.raw_value()};
  }

 private:
  matrix_pair m_;
};

template <space_type A, space_type B>
using map = basic_map<mode_space<A>, mode_space<B>>;
template <space_type A, space_type B>
using projective_map = basic_projective_map<mode_space<A>, mode_space<B>>;

template <class A, class B>
struct raw_access<basic_map<A, B>> {
  using raw_type = matrix_pair;
  static constexpr matrix_pair to(const basic_map<A, B>& m) { return m.raw_value(); }
  static constexpr basic_map<A, B> from(matrix_pair m) { return {detail::raw_tag{}, m}; }
};
template <class A, class B>
struct raw_access<basic_projective_map<A, B>> {
  using raw_type = matrix_pair;
  static constexpr matrix_pair to(const basic_projective_map<A, B>& m) { return m.raw_value(); }
  static constexpr basic_projective_map<A, B> from(matrix_pair m) { return {detail::raw_tag{}, m}; }
};

/// The forward matrix, for uploading to a shader (glUniformMatrix4fv).
template <class A, class B>
constexpr mat4_rep matrix(const basic_map<A, B>& m) {
  return m.raw_value().forward;
}
template <class A, class B>
constexpr mat4_rep matrix(const basic_projective_map<A, B>& m) {
  return m.raw_value().forward;
}
/// The 3x3 matrix that transforms normals (inverse transpose), for shaders.
template <class A, class B>
constexpr mat3_rep normal_matrix(const basic_map<A, B>& m) {
  return glm::transpose(mat3_rep(m.raw_value().inverse));
}

template <class A, class B>
constexpr basic_map<B, A> inverse(const basic_map<A, B>& m) {
  return {detail::raw_tag{}, {m.raw_value().inverse, m.raw_value().forward}};
}
template <class A, class B>
constexpr basic_projective_map<B, A> inverse(const basic_projective_map<A, B>& m) {
  return {detail::raw_tag{}, {m.raw_value().inverse, m.raw_value().forward}};
}

/// Composition where spaces meet: map<B, C> * map<A, B> is map<A, C> (apply the right one first).
template <class B, class C, class A, class B2>
diagnose::maps_do_not_meet<diagnose::outer<diagnose::map<B, C>>, diagnose::inner<diagnose::map<A, B2>>>
operator*(const basic_map<B, C>&, const basic_map<A, B2>&);
template <class B, class C, class A, class B2>
  requires rules::same_space<B, B2>
constexpr basic_map<A, C> operator*(const basic_map<B, C>& outer, const basic_map<A, B2>& inner) {
  return basic_map<A, C>(detail::raw_tag{}, compose(outer.raw_value(), inner.raw_value()));
}
template <class B, class C, class A, class B2>
diagnose::maps_do_not_meet<diagnose::outer<diagnose::map<B, C>>, diagnose::inner<diagnose::map<A, B2>>>
operator*(const basic_projective_map<B, C>&, const basic_map<A, B2>&);
template <class B, class C, class A, class B2>
  requires rules::same_space<B, B2>
constexpr basic_projective_map<A, C> operator*(const basic_projective_map<B, C>& outer,
                                               const basic_map<A, B2>& inner) {
  return basic_projective_map<A, C>(detail::raw_tag{}, compose(outer.raw_value(), inner.raw_value()));
}
template <class B, class C, class A, class B2>
diagnose::maps_do_not_meet<diagnose::outer<diagnose::map<B, C>>, diagnose::inner<diagnose::map<A, B2>>>
operator*(const basic_map<B, C>&, const basic_projective_map<A, B2>&);
template <class B, class C, class A, class B2>
  requires rules::same_space<B, B2>
constexpr basic_projective_map<A, C> operator*(const basic_map<B, C>& outer,
                                               const basic_projective_map<A, B2>& inner) {
  return basic_projective_map<A, C>(detail::raw_tag{}, compose(outer.raw_value(), inner.raw_value()));
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
