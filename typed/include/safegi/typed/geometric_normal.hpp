// Geometric versus shading normals, opt-in. normal<S> stays what it was: any unit
// normal, in practice the shading normal (interpolated, bumped, normal-mapped).
// geometric_normal<S> is the true surface's normal (a triangle's face normal): a normal
// everywhere else (it derives from one), but asked for by what needs the real surface, such
// as the side a ray leaves from. There an interpolated or bumped normal leaks light
// through the surface or lets a ray hit the surface it left; a plain normal<S> given to
// such a function is the report diagnose::shading_normal_as_geometric.
//
//   const sg::geometric_normal<world> ng = sg::face_normal(p0, p1, p2);
//   const sg::point<world> origin = sg::offset_ray_origin(p, ng, epsilon, wi);
//
// Unchecked, geometric_normal<S> is normal<S> and the functions are the same arithmetic.
//
// Cost, measured: not proven free. A kernel offset_ray_origin(p0, face_normal(p0, p1, p2),
// eps, w) compiled checked and unchecked (GCC 12, -O2, testsuite/zero_overhead's flags)
// gives bodies of the same length whose instructions are scheduled and allocated
// differently, also with geometric_normal a sibling of normal instead of a class derived
// from it; face_normal alone gives the same instructions in a stack frame 16 bytes larger
// (GCC keeps a slot for the geometric_normal temporary, as for a named shaded_point). So it
// is not in the zero-overhead kernel list. Until that is understood, use it where a few
// instructions do not matter (ray spawning), not in the traversal loop.
#pragma once

#include <type_traits>

#include "safegi/typed/space.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// The normal of the true surface. Use the alias geometric_normal<S>.
template <class S>
class basic_geometric_normal : public basic_normal<S> {
 public:
  constexpr basic_geometric_normal(detail::raw_tag, vec3_rep xyz) : basic_normal<S>(detail::raw_tag{}, xyz) {}
  /// A normal<S> is not known to be the geometric one: face_normal(p0, p1, p2), or state it.
  template <class Report = diagnose::shading_normal_as_geometric<S>>
  SAFEGI_MISTAKE basic_geometric_normal(const basic_normal<S>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a shading normal (interpolated, bumped) is not the surface's: face_normal(p0, p1, p2), or geometric(n) for a normal known to be the true surface's");  // NOLINT
  /// Flipped, still the surface's normal.
  constexpr basic_geometric_normal operator-() const { return {detail::raw_tag{}, -this->raw_value()}; }
};

template <space_type S>
using geometric_normal = std::conditional_t<is_checked, basic_geometric_normal<mode_space<S>>, normal<S>>;

template <class S>
struct raw_access<basic_geometric_normal<S>> : detail::raw_access_by_member<basic_geometric_normal<S>, vec3_rep> {};

/// States that n is the true surface's normal (greppable, like a cast).
template <class S>
constexpr auto geometric(basic_normal<S> n) {
  if constexpr (is_checked)
    return basic_geometric_normal<S>(detail::raw_tag{}, n.raw_value());
  else
    return n;
}

/// The normal of the triangle p0 p1 p2 (counter-clockwise seen from its front): the
/// geometric normal by construction. The triangle must not be degenerate.
template <class S, class S1, class S2>
diagnose::space_mismatch<diagnose::op::cross, S, std::conditional_t<std::is_same_v<S, S1>, S2, S1>>
face_normal(basic_point<S>, basic_point<S1>, basic_point<S2>);
template <class S, class S1, class S2>
  requires rules::same_space<S, S1> && rules::same_space<S, S2>
constexpr auto face_normal(basic_point<S> p0, basic_point<S1> p1, basic_point<S2> p2) {
  const vec3_rep n = glm::normalize(glm::cross(p1.raw_value() - p0.raw_value(), p2.raw_value() - p0.raw_value()));
  if constexpr (is_checked)
    return basic_geometric_normal<S>(detail::raw_tag{}, n);
  else
    return basic_normal<S>(detail::raw_tag{}, n);
}

/// A ray origin moved off the surface at p by epsilon along the geometric normal, to the
/// side w leaves toward (pbrt's OffsetRayOrigin, with a fixed epsilon): the shading
/// normal's side can be the other one, and the ray then starts under the surface.
template <class S, class S2, class S3>
diagnose::space_mismatch<diagnose::op::offset_ray_origin, S, std::conditional_t<std::is_same_v<S, S2>, S3, S2>>
offset_ray_origin(basic_point<S>, basic_geometric_normal<S2>, quantity<dim::length>, basic_direction<S3>);
template <class S, class S2, class S3>
  requires rules::same_space<S, S2> && rules::same_space<S, S3>
constexpr basic_point<S> offset_ray_origin(basic_point<S> p, basic_geometric_normal<S2> ng, quantity<dim::length> epsilon,
                                           basic_direction<S3> w) {
  const vec3_rep n = ng.raw_value();
  const real e = glm::dot(n, w.raw_value()) < real(0) ? -raw(epsilon) : raw(epsilon);
  return {detail::raw_tag{}, p.raw_value() + e * n};
}
/// A plain normal<S> here is the report (checked); unchecked every normal is one type.
template <class S, class S2, class S3>
  requires(is_checked)
diagnose::shading_normal_as_geometric<S2> offset_ray_origin(basic_point<S>, basic_normal<S2>, quantity<dim::length>,
                                                            basic_direction<S3>);
template <class S, class S2, class S3>
  requires(!is_checked)
constexpr basic_point<S> offset_ray_origin(basic_point<S> p, basic_normal<S2> ng, quantity<dim::length> epsilon,
                                           basic_direction<S3> w) {
  const vec3_rep n = ng.raw_value();
  const real e = glm::dot(n, w.raw_value()) < real(0) ? -raw(epsilon) : raw(epsilon);
  return {detail::raw_tag{}, p.raw_value() + e * n};
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
