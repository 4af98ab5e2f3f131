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

using Reflectance = spectrum<dim::dimensionless>;  // albedos and path throughput
// A complex index of refraction's real part η or extinction k, per channel: a
// ratio like a reflectance (the same type), but not bounded by 1.
using IndexSpectrum = spectrum<dim::dimensionless>;
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
