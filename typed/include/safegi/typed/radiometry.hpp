// Changes of measure that the type system cannot derive by itself. The cosine at a
// light (cos θ_l in dω = cos θ_l dA / r²) is a geometric ratio, not the receiver's
// projected-cosine factor proj, so these helpers take it from dot(n_light, w) and
// say in their name what they do.
#pragma once

#include "safegi/typed/quantity.hpp"
#include "safegi/typed/units.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

/// p_ω = p_A r² / |cos θ_l|: a pdf per unit area on a light, seen from a point at squared
/// distance r², as a pdf per unit solid angle.
constexpr quantity<dim::pdf_solid_angle> pdf_area_to_solid_angle(quantity<dim::pdf_area> pdf,
                                                                quantity<dim::area> distance_squared,
                                                                quantity<dim::proj> cos_light) {
  const real cosine = raw(cos_light) < real(0) ? -raw(cos_light) : raw(cos_light);
  return pdf * distance_squared / (cosine * units::steradian);
}

/// p_A = p_ω |cos θ_l| / r²: the inverse change of measure.
constexpr quantity<dim::pdf_area> pdf_solid_angle_to_area(quantity<dim::pdf_solid_angle> pdf,
                                                         quantity<dim::area> distance_squared,
                                                         quantity<dim::proj> cos_light) {
  const real cosine = raw(cos_light) < real(0) ? -raw(cos_light) : raw(cos_light);
  return pdf * (cosine * units::steradian) / distance_squared;
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
