// Warps from the unit square to the domains the renderer samples, on plain
// floats (unit vectors around +z); callers give them their space.
#pragma once

#include <cmath>
#include <numbers>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render {

using kernel::Float3;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInversePi = 1.0f / kPi;

inline Float3 sample_cosine_hemisphere(float u1, float u2) {
  // Concentric disk mapping (Shirley–Chiu), lifted to the hemisphere.
  float a = 2 * u1 - 1, b = 2 * u2 - 1;
  float r = 0, phi = 0;
  if (a == 0 && b == 0) return {0, 0, 1};
  if (a * a > b * b) {
    r = a;
    phi = (kPi / 4) * (b / a);
  } else {
    r = b;
    phi = (kPi / 2) - (kPi / 4) * (a / b);
  }
  float x = r * std::cos(phi), y = r * std::sin(phi);
  return {x, y, std::sqrt(std::fmax(0.0f, 1 - x * x - y * y))};
}

inline void sample_concentric_disk(float u1, float u2, float& x, float& y) {
  float a = 2 * u1 - 1, b = 2 * u2 - 1;
  if (a == 0 && b == 0) {
    x = y = 0;
    return;
  }
  float r, phi;
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

inline Float3 sample_uniform_sphere(float u1, float u2) {
  float z = 1 - 2 * u1;
  float r = std::sqrt(std::fmax(0.0f, 1 - z * z));
  float phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Direction around +z with density proportional to cos^n (the Phong lobe).
inline Float3 sample_cosine_power(float u1, float u2, float exponent) {
  float cos_theta = std::pow(u1, 1.0f / (exponent + 1));
  float sin_theta = std::sqrt(std::fmax(0.0f, 1 - cos_theta * cos_theta));
  float phi = 2 * kPi * u2;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

inline float power_heuristic(float pdf_a, float pdf_b) {
  float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  if (std::isinf(a)) return 1.0f;
  return a / (a + b);
}

}  // namespace safegi::render
