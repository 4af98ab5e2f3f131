// The environment light at render time: radiance arriving from every
// direction, and directions drawn in proportion to it.
//
// A lat-long map is sampled on its (u, v) square by a piecewise-constant
// density, then mapped to the sphere by ω(u, v) = (sin θ cos φ, sin θ sin φ,
// cos θ) with φ = 2πu, θ = πv. That map stretches area: dω = sin θ dθ dφ =
// 2π² sin θ du dv, so a density p_uv per unit of (u, v) area is p_uv /
// (2π² sin θ sr) per steradian — the Jacobian below, in its own type.
#pragma once

#include <optional>

#include "lights/distribution.hpp"
#include "safegi/cpu_renderer/sampling.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// dω/d(u v) of the lat-long parameterisation at polar angle θ: the solid
// angle per unit area of the (dimensionless) map square.
inline quantity<dim::solid_angle> solid_angle_per_map_area(Real sin_theta) {
  return 2 * kPi * kPi * sin_theta * units::steradian;
}

class Environment {
 public:
  explicit Environment(const EnvironmentLight& light);

  struct Sample {
    DirectionWorld wi;  // towards the sky
    Radiance radiance;  // arriving along -wi
    PdfSolidAngle pdf = sg::zero;
  };

  // The radiance arriving at any point from direction `wi` (travelling along -wi).
  Radiance radiance(DirectionWorld wi) const;
  // A direction drawn with density pdf(wi) per steradian.
  std::optional<Sample> sample(Real u1, Real u2) const;
  PdfSolidAngle pdf(DirectionWorld wi) const;
  // The mean radiance over the sphere of directions (for choosing among lights).
  Radiance average_radiance() const;

 private:
  struct MapPoint {
    Real u, v, sin_theta;
  };
  MapPoint to_map(DirectionWorld wi) const;

  const EnvironmentLight& light_;
  map<World, LightSpace> light_from_render_;
  std::optional<Distribution2D> distribution_;  // over the map's texels; none: uniform over the sphere
};

}  // namespace safegi::render
