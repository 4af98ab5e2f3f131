// Changes of measure that the type system cannot derive by itself: the inverse-square
// law, and a pdf per area on a light seen as a pdf per solid angle.
//
// Two cosines meet in dω = cos θ_l dA / r². The receiver's cosine n·ω is the
// projected-cosine factor proj of the rendering equation; the cosine at the light,
// cos θ_l, is a geometric ratio of the change of measure. So the inverse-square law
// below is per *projected* area (the receiver's proj completes it, and forgetting it
// is still a type error), and the changes of measure take the light's normal and the
// direction instead of a cosine, so no proj has to be reinterpreted.
#pragma once

#include "safegi/typed/quantity.hpp"
#include "safegi/typed/space.hpp"
#include "safegi/typed/units.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// The inverse-square law, dω = dA⊥ / r²: the solid angle that a unit of area facing
/// the source subtends at distance r. A point light of intensity I gives the irradiance
///   quantity<dim::irradiance> E = I * solid_angle_per_projected_area(r) * dot(n, wi);
/// with the receiver's cosine, whose proj the law's "per projected area" cancels.
constexpr quantity<dim::solid_angle_per_projected_area> solid_angle_per_projected_area(quantity<dim::length> distance) {
  return real(1) * units::steradian / (distance * distance * units::proj);
}

namespace detail {
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> abs_cosine(basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr real abs_cosine(basic_normal<S> n, basic_direction<S2> w) {
  const real cosine = glm::dot(n.raw_value(), w.raw_value());
  return cosine < real(0) ? -cosine : cosine;
}
}  // namespace detail

/// p_ω = p_A r² / |cos θ_l|: a pdf per unit area on a light, seen from a point at squared
/// distance r², as a pdf per unit solid angle. cos θ_l is between the light's normal and
/// w, the direction between the two points (either way round).
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2>
pdf_area_to_solid_angle(quantity<dim::pdf_area>, quantity<dim::area>, basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::pdf_solid_angle> pdf_area_to_solid_angle(quantity<dim::pdf_area> pdf,
                                                                quantity<dim::area> distance_squared,
                                                                basic_normal<S> light_normal, basic_direction<S2> w) {
  return pdf * distance_squared / (detail::abs_cosine(light_normal, w) * units::steradian);
}

/// p_A = p_ω |cos θ_l| / r²: the inverse change of measure.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2>
pdf_solid_angle_to_area(quantity<dim::pdf_solid_angle>, quantity<dim::area>, basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::pdf_area> pdf_solid_angle_to_area(quantity<dim::pdf_solid_angle> pdf,
                                                         quantity<dim::area> distance_squared,
                                                         basic_normal<S> light_normal, basic_direction<S2> w) {
  return pdf * (detail::abs_cosine(light_normal, w) * units::steradian) / distance_squared;
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
