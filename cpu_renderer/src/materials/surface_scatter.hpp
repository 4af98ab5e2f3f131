// A surface point's scattering towards a direction: its BSDF in its shading
// frame, with pbrt-v3's rules for shading normals that differ from the
// geometric one. Shared by the path tracer's light samples and the
// bidirectional path tracer's connections.
#pragma once

#include <cmath>
#include <optional>

#include "materials/bsdf.hpp"
#include "integrators/integrator.hpp"

namespace safegi::render {

// A direction turned into the shading frame's upper hemisphere.
inline DirectionShading folded_up(DirectionShading d) {
  const Real3 v = to_kernel(d);
  return from_kernel<DirectionShading>(Real3{v.x, v.y, std::abs(v.z)});
}

// A surface point's scattering towards a light: its BSDF in its shading frame.
struct SurfaceScatter {
  const Bsdf& bsdf;
  const ShadingFrame& frame;
  DirectionShading wo;
  NormalWorld normal;  // the geometric one, on wo's side
  // The frame's normal is a bump map's or interpolated, so the shading and
  // geometric hemispheres differ (pbrt-v3's BSDF::f rule below).
  bool perturbed;
  // Importance at a light path's vertex (wo towards the light): the adjoint BSDF.
  Transport transport = Transport::radiance;

  std::optional<ScatteringDensity> towards(DirectionWorld wi_world) const {
    DirectionShading wi = frame.to_local(wi_world);
    if (perturbed && !bsdf.transmits()) {
      // pbrt-v3: the geometric normal says whether light is reflected, and a
      // reflecting BSDF's lobes then count on either side of the shading
      // normal (at a smooth mesh's silhouette the viewer can be below it, a
      // light above the surface below it). Evaluated with both directions
      // folded into the shading hemisphere: Lambert's and Oren–Nayar's value
      // is pbrt-v3's there, a glossy lobe's its mirror image's.
      if (!(sg::dot(normal, wi_world) > sg::zero)) return std::nullopt;
      Brdf f = bsdf.eval(folded_up(wo), folded_up(wi), transport);
      if (sg::is_black(f)) return std::nullopt;
      return f * sg::abs_cos_theta(wi);
    }
    const bool above = wi.z() > 0;
    if (!above && !bsdf.transmits()) return std::nullopt;
    // Through a transmitting BSDF, reflection or transmission is the geometric
    // normal's to say, as in pbrt-v3; where the shading frame puts the light on
    // the other side, nothing counts.
    if (perturbed && (sg::dot(normal, wi_world) > sg::zero) != above) return std::nullopt;
    Brdf f = bsdf.eval(wo, wi, transport);
    if (sg::is_black(f)) return std::nullopt;
    return f * sg::abs_cos_theta(wi);
  }
  PdfSolidAngle pdf(DirectionWorld wi) const { return bsdf.pdf(wo, frame.to_local(wi)); }
};

}  // namespace safegi::render
