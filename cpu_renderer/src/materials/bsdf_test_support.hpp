// What the BSDF tests share: directions by their angles and integrals over
// directions by the midpoint rule.
#pragma once

#include <cmath>

#include "materials/bsdf.hpp"

namespace safegi::render::bsdf_test {

inline constexpr double kPiD = 3.14159265358979323846;

inline DirectionShading spherical(double theta, double phi) {
  return DirectionShading(static_cast<Real>(std::sin(theta) * std::cos(phi)),
                          static_cast<Real>(std::sin(theta) * std::sin(phi)), static_cast<Real>(std::cos(theta)));
}

// ∫ g(ω) dω over the upper hemisphere by the midpoint rule in (θ, φ).
template <class G>
double hemisphere_integral(G g, int theta_steps = 1500, int phi_steps = 240) {
  double sum = 0;
  const double dtheta = kPiD / 2 / theta_steps, dphi = 2 * kPiD / phi_steps;
  for (int i = 0; i < theta_steps; ++i) {
    double theta = (i + 0.5) * dtheta;
    for (int j = 0; j < phi_steps; ++j) sum += g(spherical(theta, (j + 0.5) * dphi)) * std::sin(theta) * dtheta * dphi;
  }
  return sum;
}

// The same over the whole sphere: the upper hemisphere and the lower one.
template <class G>
double sphere_integral(G g, int theta_steps = 1500, int phi_steps = 240) {
  return hemisphere_integral(g, theta_steps, phi_steps) +
         hemisphere_integral([&](DirectionShading w) { return g(-w); }, theta_steps, phi_steps);
}

}  // namespace safegi::render::bsdf_test
