// The renderer's vocabulary of typed values.
//
// TODO(typed): temporary plain-float stand-ins until the typed library's core
// lands on branch `typed`; these aliases then become quantity<D>, spectrum<D>,
// point<S>, direction<S> and map<A, B> from <safegi/typed.hpp>.
#pragma once

#include <cmath>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render {

struct Rgb {
  float r = 0, g = 0, b = 0;

  Rgb() = default;
  constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  constexpr explicit Rgb(float v) : r(v), g(v), b(v) {}

  friend Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
  friend Rgb operator*(Rgb a, Rgb b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
  friend Rgb operator*(Rgb a, float s) { return {a.r * s, a.g * s, a.b * s}; }
  friend Rgb operator*(float s, Rgb a) { return {a.r * s, a.g * s, a.b * s}; }
  friend Rgb operator/(Rgb a, float s) { return {a.r / s, a.g / s, a.b / s}; }
  Rgb& operator+=(Rgb o) { return *this = *this + o; }
  Rgb& operator*=(Rgb o) { return *this = *this * o; }
  float max_component() const { return std::fmax(r, std::fmax(g, b)); }
  float average() const { return (r + g + b) / 3.0f; }
  bool is_black() const { return r == 0 && g == 0 && b == 0; }
};

// An affine map between two spaces (row-major 3x4).
struct Affine {
  float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  kernel::Float3 apply_point(kernel::Float3 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  kernel::Float3 apply_vector(kernel::Float3 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  friend Affine operator*(const Affine& a, const Affine& b) {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + (j == 3 ? a.m[i][3] : 0.0f);
    return r;
  }
};

using Length = float;
using Time = float;
using Angle = float;
using Reflectance = Rgb;
using Radiance = Rgb;
using Intensity = Rgb;
using PointObject = kernel::Float3;
using PointWorld = kernel::Float3;
using VectorWorld = kernel::Float3;
using ObjectToWorld = Affine;

}  // namespace safegi::render
