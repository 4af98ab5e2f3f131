// The renderer's vocabulary: typed quantities, spectra and geometry from the
// SafeGI typed library (portable API only, so the same source builds checked
// and unchecked), plus the explicit Jacobians between measures.
#pragma once

#include <safegi/typed.hpp>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render {

namespace sg = ::safegi;
namespace dim = ::safegi::dim;
namespace units = ::safegi::units;

using World = spaces::world;
using Object = spaces::object;
using Shading = spaces::shading;
using LightSpace = spaces::light;

using Length = quantity<dim::length>;
using Time = quantity<dim::time>;
using Angle = quantity<dim::angle>;
using Proj = quantity<dim::proj>;
using PdfSolidAngle = quantity<dim::pdf_solid_angle>;
using PdfArea = quantity<dim::pdf_area>;
// dω/dA and dA/dω: converting densities between solid-angle and area measure.
using SolidAnglePerArea = quantity<dim::quotient<dim::solid_angle, dim::area>>;
using AreaPerSolidAngle = quantity<dim::quotient<dim::area, dim::solid_angle>>;

using Reflectance = spectrum<dim::dimensionless>;  // albedos and path throughput
using Radiance = spectrum<dim::radiance>;
using Intensity = spectrum<dim::intensity>;
using Brdf = spectrum<dim::brdf>;

using PointObject = point<Object>;
using PointWorld = point<World>;
using VectorWorld = vector<World>;
using DirectionWorld = direction<World>;
using NormalWorld = normal<World>;
using DirectionShading = direction<Shading>;
using RenderFromObject = map<Object, World>;
using RenderFromLight = map<LightSpace, World>;
using ShadingFrame = frame<World, Shading>;

// Solid angle subtended per unit of area at distance r whose normal makes
// angle θ with the line of sight: dω/dA = cos θ / r². The cosine is the
// geometric factor of the change of measure, hence the explicit cast.
inline SolidAnglePerArea solid_angle_per_area(Proj cos_theta, Length distance) {
  return sg::dimension_cast<dim::quotient<dim::solid_angle, dim::area>>(cos_theta / (distance * distance));
}

// A density over area as a density over solid angle: p_ω = p_A · dA/dω.
inline PdfSolidAngle to_solid_angle_density(PdfArea pdf, Proj cos_at_area, Length distance) {
  return pdf / solid_angle_per_area(cos_at_area, distance);
}

// Plain components for the acceleration kernel (reference units: metres).
template <class T>
inline kernel::Real3 to_kernel(const T& value) {
  sg::vec3_rep v = sg::raw(value);
  return {v.x, v.y, v.z};
}
template <class T>
inline T from_kernel(kernel::Real3 v) {
  return sg::from_raw<T>(sg::vec3_rep(v.x, v.y, v.z));
}

}  // namespace safegi::render
