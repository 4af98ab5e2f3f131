// Plain arithmetic for the acceleration kernel, in the renderer's precision
// (Real: float, or double in the double-precision build, SAFEGI_DOUBLE=1).
//
// The BVH and the ray-primitive tests are an index structure over world-space
// metres: they take a typed ray, do their arithmetic here on plain numbers, and
// hand back a typed hit (see geometry.hpp). Keeping the inner loop on a small
// plain vector type makes it identical in the checked and unchecked builds.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <safegi/typed/config.hpp>

namespace safegi::render {
// The representation of every geometric and radiometric value.
using Real = ::safegi::real;
// Its name, for messages about its range and precision.
inline constexpr const char* kRealName = sizeof(Real) == sizeof(float) ? "float" : "double";
}  // namespace safegi::render

namespace safegi::render::kernel {

// The unsigned integer with Real's bits, for stepping to a neighbouring value.
using RealBits = std::conditional_t<sizeof(Real) == 4, uint32_t, uint64_t>;

inline constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

struct Real3 {
  Real x = 0, y = 0, z = 0;

  Real operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  Real& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
  friend Real3 operator+(Real3 a, Real3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Real3 operator-(Real3 a, Real3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Real3 operator*(Real3 a, Real s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Real3 operator*(Real s, Real3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend Real3 operator*(Real3 a, Real3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
};

inline Real dot(Real3 a, Real3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Real3 cross(Real3 a, Real3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real3 abs(Real3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
inline Real3 min(Real3 a, Real3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Real3 max(Real3 a, Real3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
inline Real length(Real3 a) { return std::sqrt(dot(a, a)); }
inline Real3 normalize(Real3 a) { return a * (1.0f / length(a)); }
inline Real max_component(Real3 a) { return std::max(a.x, std::max(a.y, a.z)); }

// Rounding-error bound of n floating-point operations (pbrt's gamma(n)).
constexpr Real gamma(int n) {
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon() * 0.5f;
  return (n * epsilon) / (1 - n * epsilon);
}

inline Real next_float_up(Real v) {
  if (std::isinf(v) && v > 0) return v;
  if (v == Real(-0.0)) v = Real(0);
  RealBits bits = std::bit_cast<RealBits>(v);
  bits = v >= 0 ? bits + 1 : bits - 1;
  return std::bit_cast<Real>(bits);
}

inline Real next_float_down(Real v) {
  if (std::isinf(v) && v < 0) return v;
  if (v == Real(0)) v = Real(-0.0);
  RealBits bits = std::bit_cast<RealBits>(v);
  bits = v > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<Real>(bits);
}

// Moves a point off a surface by its rounding-error box so that a ray leaving
// it on the side of `w` cannot hit the surface it started on, whatever the
// scene's scale (pbrt-v3 §3.9.5).
inline Real3 offset_ray_origin(Real3 p, Real3 error, Real3 n, Real3 w) {
  Real d = dot(abs(n), error);
  Real3 offset = n * d;
  if (dot(w, n) < 0) offset = offset * -1.0f;
  Real3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0) po[i] = next_float_up(po[i]);
    else if (offset[i] < 0) po[i] = next_float_down(po[i]);
  }
  return po;
}

struct Bounds3 {
  Real3 lower{std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity(),
               std::numeric_limits<Real>::infinity()};
  Real3 upper{-std::numeric_limits<Real>::infinity(), -std::numeric_limits<Real>::infinity(),
               -std::numeric_limits<Real>::infinity()};

  void extend(Real3 p) {
    lower = min(lower, p);
    upper = max(upper, p);
  }
  void extend(const Bounds3& b) {
    lower = min(lower, b.lower);
    upper = max(upper, b.upper);
  }
  Real3 centroid() const { return (lower + upper) * 0.5f; }
  Real3 extent() const { return upper - lower; }
  bool empty() const { return lower.x > upper.x; }
  Real surface_area() const {
    if (empty()) return 0.0f;
    Real3 d = extent();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  int widest_axis() const {
    Real3 d = extent();
    return d.x > d.y && d.x > d.z ? 0 : (d.y > d.z ? 1 : 2);
  }
};

}  // namespace safegi::render::kernel
