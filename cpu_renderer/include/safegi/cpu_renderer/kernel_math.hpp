// Plain float arithmetic for the acceleration kernel.
//
// The BVH and the ray-primitive tests are an index structure over world-space
// metres: they take a typed ray, do their arithmetic here on floats, and hand
// back a typed hit (see geometry.hpp). Keeping the inner loop on a small plain
// vector type makes it identical in the checked and unchecked builds.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace safegi::render::kernel {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Float3 {
  float x = 0, y = 0, z = 0;

  float operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  float& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
  friend Float3 operator+(Float3 a, Float3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Float3 operator-(Float3 a, Float3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Float3 operator*(Float3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Float3 operator*(float s, Float3 a) { return {a.x * s, a.y * s, a.z * s}; }
  friend Float3 operator*(Float3 a, Float3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
};

inline float dot(Float3 a, Float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Float3 cross(Float3 a, Float3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Float3 abs(Float3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
inline Float3 min(Float3 a, Float3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Float3 max(Float3 a, Float3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
inline float length(Float3 a) { return std::sqrt(dot(a, a)); }
inline Float3 normalize(Float3 a) { return a * (1.0f / length(a)); }
inline float max_component(Float3 a) { return std::max(a.x, std::max(a.y, a.z)); }

// Rounding-error bound of n floating-point operations (pbrt's gamma(n)).
constexpr float gamma(int n) {
  constexpr float epsilon = std::numeric_limits<float>::epsilon() * 0.5f;
  return (n * epsilon) / (1 - n * epsilon);
}

inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0) return v;
  if (v == -0.0f) v = 0.0f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v >= 0 ? bits + 1 : bits - 1;
  return std::bit_cast<float>(bits);
}

inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0) return v;
  if (v == 0.0f) v = -0.0f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<float>(bits);
}

// Moves a point off a surface by its rounding-error box so that a ray leaving
// it on the side of `w` cannot hit the surface it started on, whatever the
// scene's scale (pbrt-v3 §3.9.5).
inline Float3 offset_ray_origin(Float3 p, Float3 error, Float3 n, Float3 w) {
  float d = dot(abs(n), error);
  Float3 offset = n * d;
  if (dot(w, n) < 0) offset = offset * -1.0f;
  Float3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0) po[i] = next_float_up(po[i]);
    else if (offset[i] < 0) po[i] = next_float_down(po[i]);
  }
  return po;
}

struct Bounds3 {
  Float3 lower{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
               std::numeric_limits<float>::infinity()};
  Float3 upper{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
               -std::numeric_limits<float>::infinity()};

  void extend(Float3 p) {
    lower = min(lower, p);
    upper = max(upper, p);
  }
  void extend(const Bounds3& b) {
    lower = min(lower, b.lower);
    upper = max(upper, b.upper);
  }
  Float3 centroid() const { return (lower + upper) * 0.5f; }
  Float3 extent() const { return upper - lower; }
  bool empty() const { return lower.x > upper.x; }
  float surface_area() const {
    if (empty()) return 0.0f;
    Float3 d = extent();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  int widest_axis() const {
    Float3 d = extent();
    return d.x > d.y && d.x > d.z ? 0 : (d.y > d.z ? 1 : 2);
  }
};

}  // namespace safegi::render::kernel
