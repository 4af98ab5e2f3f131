#include "accel/triangle_block.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "accel/bvh.hpp"  // cpu_has_avx2, SAFEGI_TARGET_AVX2

namespace safegi::render::kernel {
namespace {

constexpr int kWidth = TriangleBlock::kWidth;

// The lanes the exact test accepts, each tested with the same t_max.
unsigned exact_hits(const TriangleBlock& block, const BlockRay& ray, Real t_max, int count) {
  unsigned lanes = 0;
  for (int lane = 0; lane < count; ++lane) {
    Real t = t_max, b1, b2;
    if (intersect_lane(block, lane, ray, t, b1, b2)) lanes |= 1u << lane;
  }
  return lanes;
}

// The filter over two blocks as one vector of eight lanes, compiled for AVX2
// as the AVX2 traversal has it (only called where the CPU has AVX2).
SAFEGI_TARGET_AVX2 unsigned candidate_pair_avx2(const TriangleBlock (&blocks)[2], const BlockRay& ray, Real t_max,
                                                int count) {
  return candidate_lanes<2 * kWidth>(blocks[0], ray, t_max, count);
}

// The eight-lane filter over `blocks` must keep exactly what the four-lane one
// keeps of each block: lane for lane the same arithmetic.
void check_pair(const TriangleBlock (&blocks)[2], const BlockRay& ray, Real t_max) {
  for (int count = kWidth + 1; count <= 2 * kWidth; ++count) {
    const unsigned expected = candidate_lanes(blocks[0], ray, t_max, kWidth) |
                              candidate_lanes(blocks[1], ray, t_max, count - kWidth) << kWidth;
    ASSERT_EQ(candidate_lanes<2 * kWidth>(blocks[0], ray, t_max, count), expected) << "count " << count;
    if (cpu_has_avx2()) {
      ASSERT_EQ(candidate_pair_avx2(blocks, ray, t_max, count), expected) << "count " << count;
    }
  }
}

struct Tally {
  int exact = 0;         // lanes the exact test hit
  int missed_kept = 0;   // lanes the filter kept that the exact test missed
  int missed = 0;        // lanes the exact test missed
};

// Four random triangles around `center`, edges about `size` long, and rays
// aimed at points around them (inside, just outside and, with `on_edges`, on
// the edges and corners) from `distance` away; the filter must keep every lane
// the exact test hits.
void check_scale(std::mt19937& rng, Real3 center, Real size, Real distance, int rounds, bool on_edges,
                 Tally& tally) {
  std::uniform_real_distribution<Real> unit(-1.0f, 1.0f), barycentric(-0.2f, 1.2f);
  std::uniform_int_distribution<int> pick(on_edges ? 0 : 4, 6);
  for (int round = 0; round < rounds; ++round) {
    TriangleBlock block;
    Real3 vertex[kWidth], e1[kWidth], e2[kWidth];
    for (int lane = 0; lane < kWidth; ++lane) {
      vertex[lane] = center + Real3{unit(rng), unit(rng), unit(rng)} * size;
      e1[lane] = Real3{unit(rng), unit(rng), unit(rng)} * size;
      // Every third triangle shares its first edge with the previous lane's: rays at it test a crack.
      e2[lane] = lane > 0 && round % 3 == 0 ? e1[lane - 1] : Real3{unit(rng), unit(rng), unit(rng)} * size;
      block.set(lane, vertex[lane], e1[lane], e2[lane], 0, 0);
    }
    const int target = round % kWidth;
    Real u, v;
    switch (pick(rng)) {
      case 0: u = 0, v = std::fabs(unit(rng)); break;                // on the edge v axis
      case 1: u = std::fabs(unit(rng)), v = 0; break;                // on the edge u axis
      case 2: u = std::fabs(unit(rng)), v = 1 - u; break;            // on the far edge
      case 3: u = 0, v = 0; break;                                   // at the vertex
      default: u = barycentric(rng), v = barycentric(rng); break;    // inside or around
    }
    const Real3 aim = vertex[target] + e1[target] * u + e2[target] * v;
    const Real3 origin = aim + normalize(Real3{unit(rng), unit(rng), unit(rng)}) * distance;
    const BlockRay ray(origin, normalize(aim - origin));
    const Real limits[] = {kInfinity, distance * 1.5f, distance, distance * 0.5f};
    // The same triangles in a second block, lanes reversed: the pair's upper half.
    TriangleBlock blocks[2] = {block, block};
    for (int lane = 0; lane < kWidth; ++lane)
      blocks[1].set(kWidth - 1 - lane, vertex[lane], e1[lane], e2[lane], 0, 0);
    for (Real t_max : limits) {
      ASSERT_NO_FATAL_FAILURE(check_pair(blocks, ray, t_max));
      for (int count = 1; count <= kWidth; ++count) {
        const unsigned exact = exact_hits(block, ray, t_max, count);
        const unsigned kept = candidate_lanes(block, ray, t_max, count);
        ASSERT_EQ(exact & ~kept, 0u) << "size " << size << " distance " << distance << " center " << center.x
                                     << " t_max " << t_max << " round " << round;
        ASSERT_EQ(kept >> count, 0u) << "a lane past the leaf's count was kept";
        if (count != kWidth) continue;
        tally.exact += std::popcount(exact);
        tally.missed += kWidth - std::popcount(exact);
        tally.missed_kept += std::popcount(kept & ~exact);
      }
    }
  }
}

TEST(TriangleBlock, FilterKeepsEveryTriangleTheExactTestHits) {
  std::mt19937 rng(11);
  for (Real size : {1e-4f, 1e-2f, 1.0f, 1e3f, 1e7f})
    for (Real distance : {size * 1e-3f, size, size * 1e3f})
      for (Real offset : {0.0f, 1e4f, 1e7f}) {
        Tally tally;
        ASSERT_NO_FATAL_FAILURE(
            check_scale(rng, Real3{offset, -offset, offset * 0.5f}, size, distance, 300, true, tally));
        // Far enough from the origin a small triangle's corners round together: no area, no hits.
        if (size > offset * 1e-4f) {
          EXPECT_GT(tally.exact, 0) << "size " << size << " distance " << distance;
        }
      }
}

// The filter's point: at ordinary scales it passes on few of the lanes the ray
// misses (rays within its error bound of an edge are left to the exact test:
// 1.8 % of these misses, aimed from 200 triangle sizes away).
TEST(TriangleBlock, FilterDropsMostMisses) {
  std::mt19937 rng(12);
  Tally tally;
  ASSERT_NO_FATAL_FAILURE(check_scale(rng, Real3{0.3f, -0.2f, 1.0f}, 0.01f, 2.0f, 3000, false, tally));
  ASSERT_GT(tally.missed, 10000);
  EXPECT_LT(tally.missed_kept, tally.missed * 3 / 100) << tally.missed_kept << " of " << tally.missed;
}

TEST(TriangleBlock, DegenerateTrianglesAndNanRaysNeverHit) {
  TriangleBlock block;
  block.set(0, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0, 0);  // collinear edges: no area
  block.set(1, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0);  // a point
  block.set(2, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 0);
  block.set(3, {0, 0, 0}, {1e-30f, 0, 0}, {0, 1e-30f, 0}, 0, 0);  // below the filter's reliable range: kept, then decided
  const BlockRay down({0.25f, 0.25f, 1}, {0, 0, -1});
  EXPECT_EQ(exact_hits(block, down, kInfinity, kWidth), 0b0100u);
  EXPECT_EQ(candidate_lanes(block, down, kInfinity, kWidth) & 0b0100u, 0b0100u);
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const BlockRay broken({0.25f, 0.25f, 1}, {nan, 0, -1});
  EXPECT_EQ(exact_hits(block, broken, kInfinity, kWidth), 0u);
}

TEST(TriangleBlock, ExactTestGivesTheHitsDistanceAndBarycentrics) {
  TriangleBlock block;
  block.set(2, {1, 2, 3}, {2, 0, 0}, {0, 4, 0}, 7, 9);
  Real t = kInfinity, b1 = 0, b2 = 0;
  ASSERT_TRUE(intersect_lane(block, 2, BlockRay({1.5f, 3, 8}, {0, 0, -1}), t, b1, b2));
  EXPECT_FLOAT_EQ(t, 5);
  EXPECT_FLOAT_EQ(b1, 0.25f);
  EXPECT_FLOAT_EQ(b2, 0.25f);
  EXPECT_EQ(block.shape[2], 7u);
  EXPECT_EQ(block.face[2], 9u);
  Real nearer = 4;  // a hit beyond t_max is no hit, and t_max stays
  EXPECT_FALSE(intersect_lane(block, 2, BlockRay({1.5f, 3, 8}, {0, 0, -1}), nearer, b1, b2));
  EXPECT_EQ(nearer, 4);
}

}  // namespace
}  // namespace safegi::render::kernel
