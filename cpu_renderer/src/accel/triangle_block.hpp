// Four triangles side by side, as a BVH leaf holds them, and their ray test in
// two steps: a vector test of all four in the kernel's precision whose error
// bounds only ever let it keep a triangle it is unsure of (`candidate_lanes`),
// then the exact test in double of each one kept (`intersect_lane`). Which
// triangles a ray hits, and where, is decided by the double test alone, so the
// vector step changes the speed and never the answer.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "accel/lanes.hpp"
#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render::kernel {

// Three cache lines: a lane's vertex and edges, one array per coordinate so
// that each is one vector load for all four lanes.
struct alignas(64) TriangleBlock {
  static constexpr int kWidth = 4;
  Real p0[3][kWidth];
  Real e1[3][kWidth];
  Real e2[3][kWidth];
  Real edge_bound[kWidth];  // the largest |component| of e1 and e2: the scale of the filter's error bounds
  uint32_t shape[kWidth];
  uint32_t face[kWidth];  // the triangle's index within its shape

  void set(int lane, Real3 vertex, Real3 edge1, Real3 edge2, uint32_t shape_index, uint32_t face_index) {
    for (int axis = 0; axis < 3; ++axis) {
      p0[axis][lane] = vertex[axis];
      e1[axis][lane] = edge1[axis];
      e2[axis][lane] = edge2[axis];
    }
    edge_bound[lane] = std::max(max_component(abs(edge1)), max_component(abs(edge2)));
    shape[lane] = shape_index;
    face[lane] = face_index;
  }
  Real3 vertex(int lane) const { return {p0[0][lane], p0[1][lane], p0[2][lane]}; }
  Real3 edge1(int lane) const { return {e1[0][lane], e1[1][lane], e1[2][lane]}; }
  Real3 edge2(int lane) const { return {e2[0][lane], e2[1][lane], e2[2][lane]}; }
};

// A ray as the block test reads it: origin, unit direction and the largest
// |component| of the direction (1 for a unit vector, up to rounding).
struct BlockRay {
  Real3 origin;
  Real3 direction;
  Real direction_bound;

  BlockRay(Real3 o, Real3 d) : origin(o), direction(d), direction_bound(max_component(abs(d))) {}
};

namespace triangle_block_detail {

static_assert(TriangleBlock::kWidth == 4, "one Lanes4 holds a block's lanes of a field");
// A vector cast between vector types of one size keeps the bits (GCC, Clang);
// as macros, since a function returning lanes by value makes GCC warn about
// the ABI in the double build (32-byte lanes without AVX). They name the
// caller's `Lanes` and `Mask`.
#define SAFEGI_LANE_BITS(lanes) ((Mask)(lanes))
#define SAFEGI_LANES(bits) ((Lanes)(bits))

// The helpers take and give lanes by reference: in the double build they are
// 32 bytes, which GCC would warn pass differently by value with AVX.
using AliasingLanes = Real __attribute__((vector_size(sizeof(Lanes4)), may_alias));
inline const AliasingLanes& load(const Real (&lanes)[TriangleBlock::kWidth]) {
  return *reinterpret_cast<const AliasingLanes*>(lanes);
}
// A field's lanes of `Width` / 4 consecutive blocks, `lanes` the first block's:
// the next block's are one block further on in the same array.
template <int Width>
inline void load_lanes(typename LanesOf<Width>::Type& out, const Real (&lanes)[TriangleBlock::kWidth]) {
  if constexpr (Width == TriangleBlock::kWidth) {
    out = load(lanes);
  } else {
    static_assert(Width == 2 * TriangleBlock::kWidth, "one or two blocks");
    const auto& next = *reinterpret_cast<const AliasingLanes*>(reinterpret_cast<const char*>(lanes) +
                                                                sizeof(TriangleBlock));
    out = __builtin_shufflevector(load(lanes), next, 0, 1, 2, 3, 4, 5, 6, 7);
  }
}

// Magnitudes between these keep every product below exact enough for the
// bounds (no underflow to subnormals, no overflow); a lane outside is kept.
inline constexpr Real kSmallestReliable = Real(1e-30);
inline constexpr Real kLargestReliable = Real(1e15);
// Möller–Trumbore's quantities in the kernel's precision are within c·u of
// S·E·D (u the unit roundoff; S, E, D the largest |component| of origin − p0,
// of the edges and of the direction) with c below 50, counting the rounding of
// the comparisons below; the exact test in double adds its own, far smaller.
// 256 leaves room for both.
inline constexpr Real kErrorFactor = 256 * std::numeric_limits<Real>::epsilon() / 2;

}  // namespace triangle_block_detail

// Bit i set: lane i (of the first `count`) may be hit before `t_max` by the
// exact test; every lane that test would accept is set. `Width` 4 tests
// `block`; 8 tests it and the block after it (lane 4 + i: the next one's lane
// i) in one vector of eight, as AVX2 code does.
template <int Width = TriangleBlock::kWidth>
inline unsigned candidate_lanes(const TriangleBlock& block, const BlockRay& ray, Real t_max, int count) {
  using namespace triangle_block_detail;
  using Lanes = typename LanesOf<Width>::Type;
  using Mask = decltype(Lanes{} < Lanes{});
  Lanes p0x, p0y, p0z, e1x, e1y, e1z, e2x, e2y, e2z, edge;
  load_lanes<Width>(p0x, block.p0[0]);
  load_lanes<Width>(p0y, block.p0[1]);
  load_lanes<Width>(p0z, block.p0[2]);
  load_lanes<Width>(e1x, block.e1[0]);
  load_lanes<Width>(e1y, block.e1[1]);
  load_lanes<Width>(e1z, block.e1[2]);
  load_lanes<Width>(e2x, block.e2[0]);
  load_lanes<Width>(e2y, block.e2[1]);
  load_lanes<Width>(e2z, block.e2[2]);
  load_lanes<Width>(edge, block.edge_bound);
  const Lanes sx = ray.origin.x - p0x, sy = ray.origin.y - p0y, sz = ray.origin.z - p0z;
  const Real dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  // p = d × e2, det = e1 · p, U = s · p, q = s × e1, V = d · q, T = e2 · q;
  // u = U / det, v = V / det, t = T / det.
  const Lanes px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
  const Lanes det = e1x * px + e1y * py + e1z * pz;
  const Lanes qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
  // The sign of det folded into U, V and T (by its sign bit), so that every
  // test reads as det > 0.
  const Mask sign_bit = SAFEGI_LANE_BITS(-Lanes{});  // -0.0: the sign bit alone
  const Mask det_sign = SAFEGI_LANE_BITS(det) & sign_bit;
  const Lanes u = SAFEGI_LANES(SAFEGI_LANE_BITS(sx * px + sy * py + sz * pz) ^ det_sign);
  const Lanes v = SAFEGI_LANES(SAFEGI_LANE_BITS(dx * qx + dy * qy + dz * qz) ^ det_sign);
  const Lanes t = SAFEGI_LANES(SAFEGI_LANE_BITS(e2x * qx + e2y * qy + e2z * qz) ^ det_sign);
  const Mask magnitude_bits = ~sign_bit;
  const Lanes det_abs = SAFEGI_LANES(SAFEGI_LANE_BITS(det) & magnitude_bits);

  const Lanes abs_sx = SAFEGI_LANES(SAFEGI_LANE_BITS(sx) & magnitude_bits),
              abs_sy = SAFEGI_LANES(SAFEGI_LANE_BITS(sy) & magnitude_bits),
              abs_sz = SAFEGI_LANES(SAFEGI_LANE_BITS(sz) & magnitude_bits);
  const Lanes span_xy = abs_sx > abs_sy ? abs_sx : abs_sy;
  const Lanes span = span_xy > abs_sz ? span_xy : abs_sz;
  const Real direction = ray.direction_bound;
  const Lanes error_u = kErrorFactor * span * edge * direction;  // also V's
  const Lanes error_t = kErrorFactor * span * edge * edge;
  const Lanes error_det = kErrorFactor * edge * edge * direction;
  const Mask outside = (u < -error_u) | (v < -error_u) | (u + v > det_abs + error_det + 2 * error_u) |
                       (t < -error_t) | (t > t_max * det_abs + (error_t + t_max * error_det));
  // Where the bounds cannot be trusted, the exact test decides.
  const Mask unsure = (det_abs <= error_det) | (span * edge * direction < kSmallestReliable) |
                      (edge * edge * direction < kSmallestReliable) | (span > kLargestReliable) |
                      (edge > kLargestReliable);
  const Mask kept = ~outside | unsure;
  const unsigned lanes = lane_bits(kept);
  return lanes & ((1u << count) - 1);
}

#undef SAFEGI_LANE_BITS
#undef SAFEGI_LANES

namespace triangle_block_detail {

struct Double3 {
  double x, y, z;
  friend Double3 operator-(Double3 a, Double3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
};
inline Double3 to_double(Real3 v) { return {v.x, v.y, v.z}; }
inline double dot(Double3 a, Double3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Double3 cross(Double3 a, Double3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace triangle_block_detail

namespace triangle_block_detail {

inline uint64_t bits_of(Real x) { return std::bit_cast<std::conditional_t<sizeof(Real) == 8, uint64_t, uint32_t>>(x); }

}  // namespace triangle_block_detail

// Two triangles in one plane (a box's bottom on a floor) meet a ray at the
// same rounded t: which one the ray sees is a fair coin of the ray and the
// later-found triangle, so that each is seen about half the time, as pbrt-v3's
// float arithmetic has it, whatever the hierarchy's order.
inline bool wins_tie(const BlockRay& ray, uint32_t shape, uint32_t face) {
  using triangle_block_detail::bits_of;
  // Origin and direction both: an orthographic camera's rays share one direction.
  uint64_t h = bits_of(ray.direction.x) * 0x9E3779B97F4A7C15ull ^ bits_of(ray.direction.y) * 0xC2B2AE3D27D4EB4Full ^
               bits_of(ray.direction.z) * 0x165667B19E3779F9ull ^ bits_of(ray.origin.x) * 0x94D049BB133111EBull ^
               bits_of(ray.origin.y) * 0xD6E8FEB86659FD93ull ^ bits_of(ray.origin.z) * 0xA0761D6478BD642Full ^
               ((uint64_t{shape} << 32) | face) * 0xBF58476D1CE4E5B9ull;
  h ^= h >> 31;
  h *= 0xFF51AFD7ED558CCDull;
  h ^= h >> 33;
  return (h >> 63) != 0;
}

// Möller–Trumbore in double: in float its u, v and t carry an absolute error
// that grows with |origin − p0| and the edge lengths, which opens metre-wide
// cracks along the shared edges of 1e7 m triangles. The data stays in the
// kernel's precision. On a hit before `t_max`, lowers it and gives the
// barycentrics of p0 + b1 e1 + b2 e2.
inline bool intersect_lane(const TriangleBlock& block, int lane, const BlockRay& ray, Real& t_max, Real& b1,
                           Real& b2) {
  using namespace triangle_block_detail;
  const Double3 d = to_double(ray.direction), e1 = to_double(block.edge1(lane)), e2 = to_double(block.edge2(lane));
  const Double3 p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0.0) return false;
  const double inverse_det = 1.0 / det;
  const Double3 s = to_double(ray.origin) - to_double(block.vertex(lane));
  const double u = dot(s, p) * inverse_det;
  if (u < 0.0 || u > 1.0) return false;
  const Double3 q = cross(s, e1);
  const double v = dot(d, q) * inverse_det;
  if (v < 0.0 || u + v > 1.0) return false;
  const Real t = static_cast<Real>(dot(e2, q) * inverse_det);
  if (!(t > 0 && (t < t_max || (t == t_max && wins_tie(ray, block.shape[lane], block.face[lane]))))) return false;
  t_max = t;
  b1 = static_cast<Real>(u);
  b2 = static_cast<Real>(v);
  return true;
}

}  // namespace safegi::render::kernel
