#include "bvh.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geometry.hpp"

namespace safegi::render {
namespace {

using kernel::Real3;

// Every BVH answer must equal a brute-force loop over the same primitives.
TEST(Bvh, MatchesBruteForceOnRandomTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> coordinate(-1.0f, 1.0f), small(-0.1f, 0.1f);
  struct Tri {
    Real3 a, b, c;
  };
  std::vector<Tri> triangles;
  PrimitiveSet set;
  for (uint32_t i = 0; i < 500; ++i) {
    Real3 center{coordinate(rng), coordinate(rng), coordinate(rng)};
    Tri t{center + Real3{small(rng), small(rng), small(rng)}, center + Real3{small(rng), small(rng), small(rng)},
          center + Real3{small(rng), small(rng), small(rng)}};
    triangles.push_back(t);
    set.add_triangle(t.a, t.b, t.c, i, i);
  }
  set.build();
  // One single-triangle set per triangle: the same Möller–Trumbore test, no hierarchy.
  std::vector<PrimitiveSet> singles(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    singles[i].add_triangle(triangles[i].a, triangles[i].b, triangles[i].c, 0, 0);
    singles[i].build();
  }
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    Real3 origin{coordinate(rng) * 2, coordinate(rng) * 2, coordinate(rng) * 2};
    Real3 direction = kernel::normalize(Real3{coordinate(rng), coordinate(rng), coordinate(rng)});
    kernel::Ray ray{origin, direction, 0.0f};
    Real best = kernel::kInfinity;
    for (const PrimitiveSet& single : singles)
      if (auto hit = single.intersect(ray, best)) best = hit->distance;
    std::optional<kernel::Hit> hit = set.intersect(ray, kernel::kInfinity);
    ASSERT_EQ(hit.has_value(), best < kernel::kInfinity);
    if (hit) {
      EXPECT_EQ(hit->distance, best);
      ++hits;
    }
    EXPECT_EQ(set.occluded(ray, kernel::kInfinity), best < kernel::kInfinity);
  }
  EXPECT_GT(hits, 100);
}

TEST(Bvh, DegenerateInputStaysShallow) {
  // Thousands of identical triangles: no SAH split exists; the build must still finish.
  PrimitiveSet set;
  for (uint32_t i = 0; i < 70000; ++i) set.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, i, i);
  set.build();
  kernel::Ray ray{{0.2f, 0.2f, 1.0f}, {0, 0, -1}, 0.0f};
  std::optional<kernel::Hit> hit = set.intersect(ray, kernel::kInfinity);
  ASSERT_TRUE(hit.has_value());
  EXPECT_FLOAT_EQ(hit->distance, 1.0f);
}

TEST(Bvh, SpheresFromOutsideAndInside) {
  PrimitiveSet set;
  set.add_sphere({0, 0, 0}, 2.0f, 0);
  set.build();
  auto outside = set.intersect({{0, 0, 10}, {0, 0, -1}, 0.0f}, kernel::kInfinity);
  ASSERT_TRUE(outside);
  EXPECT_FLOAT_EQ(outside->distance, 8.0f);
  auto inside = set.intersect({{0, 0, 0}, {1, 0, 0}, 0.0f}, kernel::kInfinity);
  ASSERT_TRUE(inside);
  EXPECT_FLOAT_EQ(inside->distance, 2.0f);
}

}  // namespace
}  // namespace safegi::render
