// Participating media as pbrt-v3 traces them (its HomogeneousMedium and
// HenyeyGreenstein): Beer–Lambert transmittance, free flights sampled in one
// colour channel chosen at random (the density averaged over the three), and
// Henyey–Greenstein's phase function, sampled exactly.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "safegi/cpu_renderer/sampling.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// The phase function's own frame: its axis is the direction the light was travelling
// (built from it alone, so its azimuth is arbitrary: a normal-frame space).
struct PhaseLobe : normal_frame_tag<"phase_lobe"> {};

// Where a ray's free flight through a medium ended before `reach` (the surface
// it hits, or infinity), or that it got there, and what the path's throughput
// is multiplied by: Tr·σs / p(t) after scattering, Tr / P(t ≥ reach) otherwise.
struct FreeFlight {
  std::optional<Length> scattered_at;  // along the ray
  Reflectance weight;
};

// Beer–Lambert: the fraction of light that crosses `distance` of the medium.
inline Reflectance transmittance(const Medium& medium, Length distance) {
  // pbrt-v3 clamps the distance to the largest float, so that a channel with
  // no extinction keeps exp(0) = 1 over an infinite flight (0 · ∞ is NaN).
  const Length finite = std::min(distance, sg::from_raw<Length>(std::numeric_limits<Real>::max()));
  return sg::exp(-(medium.extinction() * finite));
}

inline FreeFlight sample_free_flight(const Medium& medium, Length reach, Real u_channel, Real u_distance) {
  const spectrum<dim::inv_length> extinction = medium.extinction();
  const int channel = std::min(static_cast<int>(u_channel * 3), 2);
  // Exponentially distributed in the chosen channel: pdf σt e^(−σt t).
  const Length flight = -std::log(1 - u_distance) / extinction[channel];
  if (flight < reach) {
    const Reflectance through = transmittance(medium, flight);
    const quantity<dim::pdf_length> density = sg::average(extinction * through);
    return {flight, through * medium.scattering / density};
  }
  const Reflectance through = transmittance(medium, reach);
  const Real probability = sg::average(through);  // of flying at least `reach`
  return {std::nullopt, probability > 0 ? through / probability : through};
}

// Henyey–Greenstein: the density of scattering from travelling along `from`
// into `to`, as pbrt-v3's PhaseHG (normalised over the sphere).
inline PdfSolidAngle henyey_greenstein(Real asymmetry, DirectionWorld from, DirectionWorld to) {
  const Real g = asymmetry, cos_theta = sg::dot(from, to);
  const Real denominator = 1 + g * g - 2 * g * cos_theta;
  return (1 - g * g) / (4 * kPi * denominator * std::sqrt(denominator)) / units::steradian;
}

// A direction drawn with density henyey_greenstein(asymmetry, from, ·).
inline DirectionWorld sample_henyey_greenstein(Real asymmetry, DirectionWorld from, Real u1, Real u2) {
  const Real g = asymmetry;
  Real cos_theta;
  if (std::abs(g) < 1e-3f) {
    cos_theta = 1 - 2 * u1;
  } else {
    const Real ratio = (1 - g * g) / (1 - g + 2 * g * u1);
    cos_theta = (1 + g * g - ratio * ratio) / (2 * g);
  }
  cos_theta = std::clamp(cos_theta, Real(-1), Real(1));
  const Real sin_theta = std::sqrt(std::max(Real(0), 1 - cos_theta * cos_theta));
  const Real phi = 2 * kPi * u2;
  auto lobe = frame<World, PhaseLobe>::from_normal(sg::to_normal(from));
  return lobe.from_local(direction<PhaseLobe>(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
}

// The medium a ray leaving a surface along `direction` travels in: the shape's
// medium on that side where it bounds two, else the one the ray was in.
inline int medium_beyond(const Shape& shape, NormalWorld geometric_normal, DirectionWorld direction, int current) {
  if (!shape.media) return current;
  return sg::dot(geometric_normal, direction) > sg::zero ? shape.media->outside : shape.media->inside;
}

}  // namespace safegi::render
