// Warps from the unit square to the domains the renderer samples, on plain
// floats (unit vectors around +z); callers give them their space.
#pragma once

#include <cmath>
#include <numbers>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render {

using kernel::Real3;

inline constexpr Real kPi = std::numbers::pi_v<Real>;
inline constexpr Real kInversePi = 1.0f / kPi;

inline void sample_concentric_disk(Real u1, Real u2, Real& x, Real& y) {
  Real a = 2 * u1 - 1, b = 2 * u2 - 1;
  if (a == 0 && b == 0) {
    x = y = 0;
    return;
  }
  Real r, phi;
  if (a * a > b * b) {
    r = a;
    phi = (kPi / 4) * (b / a);
  } else {
    r = b;
    phi = (kPi / 2) - (kPi / 4) * (a / b);
  }
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

inline Real3 sample_cosine_hemisphere(Real u1, Real u2) {
  // The concentric disk (Shirley–Chiu), lifted to the hemisphere (Malley).
  Real x, y;
  sample_concentric_disk(u1, u2, x, y);
  return {x, y, std::sqrt(std::fmax(0.0f, 1 - x * x - y * y))};
}

inline Real3 sample_uniform_sphere(Real u1, Real u2) {
  Real z = 1 - 2 * u1;
  Real r = std::sqrt(std::fmax(0.0f, 1 - z * z));
  Real phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Direction around +z with density proportional to cos^n (the Phong lobe).
inline Real3 sample_cosine_power(Real u1, Real u2, Real exponent) {
  Real cos_theta = std::pow(u1, 1.0f / (exponent + 1));
  Real sin_theta = std::sqrt(std::fmax(0.0f, 1 - cos_theta * cos_theta));
  Real phi = 2 * kPi * u2;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

inline Real power_heuristic(Real pdf_a, Real pdf_b) {
  Real a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  if (std::isinf(a)) return 1.0f;
  return a / (a + b);
}

}  // namespace safegi::render
