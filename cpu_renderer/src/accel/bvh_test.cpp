#include "accel/bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "accel/geometry.hpp"

namespace safegi::render {
namespace {

using kernel::Real3;

// The traversals a test runs its rays through: the SSE build, and the AVX2
// build where this CPU has it (the renderer's choice there). Each answer must
// be the same.
std::vector<bool> traversal_kinds() {
  if (kernel::cpu_has_avx2()) return {false, true};
  return {false};
}

// Sets which traversal the renderer takes for a scope.
class TraversalKind {
 public:
  explicit TraversalKind(bool avx2) : saved_(kernel::traversal_uses_avx2) { kernel::traversal_uses_avx2 = avx2; }
  ~TraversalKind() { kernel::traversal_uses_avx2 = saved_; }
  TraversalKind(const TraversalKind&) = delete;
  TraversalKind& operator=(const TraversalKind&) = delete;

 private:
  bool saved_;
};

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
    for (bool avx2 : traversal_kinds()) {
      TraversalKind kind(avx2);
      std::optional<kernel::Hit> hit = set.intersect(ray, kernel::kInfinity);
      ASSERT_EQ(hit.has_value(), best < kernel::kInfinity) << "avx2 " << avx2;
      if (hit) {
        EXPECT_EQ(hit->distance, best) << "avx2 " << avx2;
        EXPECT_EQ(hit->face, hit->shape);  // each triangle's own pair, through its leaf's block
        hits += !avx2;
      }
      EXPECT_EQ(set.occluded(ray, kernel::kInfinity), best < kernel::kInfinity) << "avx2 " << avx2;
    }
  }
  EXPECT_GT(hits, 100);
}

std::vector<kernel::Bounds3> random_boxes(size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> coordinate(-10.0f, 10.0f), size(0.0f, 0.2f);
  std::vector<kernel::Bounds3> boxes(count);
  for (kernel::Bounds3& box : boxes) {
    Real3 corner{coordinate(rng), coordinate(rng), coordinate(rng)};
    box.extend(corner);
    box.extend(corner + Real3{size(rng), size(rng), size(rng)});
  }
  return boxes;
}

// Large enough that subtrees and bin passes go to helper threads.
template <int Width>
void expect_hierarchy_independent_of_thread_count() {
  using Bvh = kernel::BasicBvh<Width>;
  std::vector<kernel::Bounds3> boxes = random_boxes(100000, 3);
  Bvh one(boxes, Bvh::kDefaultMaxLeafSize, 1), four(boxes, Bvh::kDefaultMaxLeafSize, 4);
  ASSERT_EQ(one.nodes().size(), four.nodes().size());
  for (size_t n = 0; n < one.nodes().size(); ++n) {
    const typename Bvh::Node &a = one.nodes()[n], &b = four.nodes()[n];
    ASSERT_EQ(a.occupied, b.occupied) << "node " << n;
    for (int i = 0; i < Width; ++i) {
      ASSERT_EQ(a.child[i], b.child[i]) << "node " << n;
      ASSERT_EQ(a.primitive_count[i], b.primitive_count[i]) << "node " << n;
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_EQ(a.lower[axis][i], b.lower[axis][i]) << "node " << n;
        ASSERT_EQ(a.upper[axis][i], b.upper[axis][i]) << "node " << n;
      }
    }
  }
  EXPECT_EQ(one.take_primitive_order(), four.take_primitive_order());
}

TEST(Bvh, HierarchyDoesNotDependOnThreadCount) { expect_hierarchy_independent_of_thread_count<4>(); }
TEST(Bvh, EightWideHierarchyDoesNotDependOnThreadCount) { expect_hierarchy_independent_of_thread_count<8>(); }

// Every primitive sits in exactly one leaf, inside every box above it.
template <int Width>
void expect_leaves_hold_each_primitive_once_inside_their_boxes() {
  using Bvh = kernel::BasicBvh<Width>;
  using Node = typename Bvh::Node;
  std::vector<kernel::Bounds3> boxes = random_boxes(30000, 4);
  Bvh bvh(boxes, Bvh::kDefaultMaxLeafSize, 2);
  const std::vector<Node> nodes = bvh.nodes();
  const std::vector<uint32_t> order = bvh.take_primitive_order();
  std::vector<int> seen(boxes.size(), 0);
  auto inside = [](const kernel::Bounds3& box, const Node& node, int i) {
    for (int axis = 0; axis < 3; ++axis)
      if (box.lower[axis] < node.lower[axis][i] || box.upper[axis] > node.upper[axis][i]) return false;
    return true;
  };
  // Depth first, with the ancestors' slots on the path.
  std::vector<std::pair<uint32_t, std::vector<std::pair<uint32_t, int>>>> pending{{0, {}}};
  while (!pending.empty()) {
    auto [index, path] = pending.back();
    pending.pop_back();
    const Node& node = nodes[index];
    for (int i = 0; i < Width; ++i) {
      if (!(node.occupied >> i & 1)) continue;
      auto child_path = path;
      child_path.push_back({index, i});
      if (node.primitive_count[i] == 0) {
        ASSERT_GT(node.child[i], index);  // depth-first layout: children after their parent
        pending.push_back({node.child[i], child_path});
        continue;
      }
      for (uint32_t k = node.child[i]; k < node.child[i] + node.primitive_count[i]; ++k) {
        ++seen[order[k]];
        for (auto [ancestor, slot] : child_path) ASSERT_TRUE(inside(boxes[order[k]], nodes[ancestor], slot));
      }
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(boxes.size()));
}

TEST(Bvh, LeavesHoldEachPrimitiveOnceInsideTheirBoxes) {
  expect_leaves_hold_each_primitive_once_inside_their_boxes<4>();
}
TEST(Bvh, EightWideLeavesHoldEachPrimitiveOnceInsideTheirBoxes) {
  expect_leaves_hold_each_primitive_once_inside_their_boxes<8>();
}

TEST(Bvh, TrianglesAndSpheresTogetherMatchBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> coordinate(-1.0f, 1.0f), small(-0.2f, 0.2f);
  // Every third primitive a sphere; each also alone in a set, for the brute force.
  PrimitiveSet set;
  std::vector<PrimitiveSet> singles(400);
  for (uint32_t i = 0; i < singles.size(); ++i) {
    Real3 center{coordinate(rng), coordinate(rng), coordinate(rng)};
    if (i % 3 == 0) {
      Real radius = 0.05f + small(rng) * small(rng);
      set.add_sphere(center, radius, i);
      singles[i].add_sphere(center, radius, i);
    } else {
      Real3 a = center + Real3{small(rng), small(rng), small(rng)};
      Real3 b = center + Real3{small(rng), small(rng), small(rng)};
      set.add_triangle(center, a, b, i, i);
      singles[i].add_triangle(center, a, b, i, i);
    }
    singles[i].build();
  }
  set.build(2);
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    kernel::Ray ray{{coordinate(rng) * 2, coordinate(rng) * 2, coordinate(rng) * 2},
                    kernel::normalize(Real3{coordinate(rng), coordinate(rng), coordinate(rng)}), 0.0f};
    Real best = kernel::kInfinity;
    uint32_t best_shape = 0;
    for (const PrimitiveSet& single : singles)
      if (auto hit = single.intersect(ray, best)) {
        best = hit->distance;
        best_shape = hit->shape;
      }
    for (bool avx2 : traversal_kinds()) {
      TraversalKind kind(avx2);
      std::optional<kernel::Hit> hit = set.intersect(ray, kernel::kInfinity);
      ASSERT_EQ(hit.has_value(), best < kernel::kInfinity) << "avx2 " << avx2;
      if (hit) {
        EXPECT_EQ(hit->distance, best) << "avx2 " << avx2;
        EXPECT_EQ(hit->shape, best_shape) << "avx2 " << avx2;
        hits += !avx2;
      }
      EXPECT_EQ(set.occluded(ray, kernel::kInfinity), best < kernel::kInfinity) << "avx2 " << avx2;
    }
  }
  EXPECT_GT(hits, 150);
}

// A NaN direction passes every slab test; the traversal must still end, with no hit.
TEST(Bvh, NanRayEndsWithoutAHit) {
  PrimitiveSet set;
  for (uint32_t i = 0; i < 1000; ++i)
    set.add_triangle({Real(i), 0, 0}, {Real(i) + 1, 0, 0}, {Real(i), 1, 0}, 0, i);
  set.build();
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  kernel::Ray ray{{0.5f, 0.25f, 1.0f}, {nan, 0, -1}, 0.0f};
  for (bool avx2 : traversal_kinds()) {
    TraversalKind kind(avx2);
    EXPECT_FALSE(set.intersect(ray, kernel::kInfinity).has_value());
    EXPECT_FALSE(set.occluded(ray, kernel::kInfinity));
  }
}

TEST(Bvh, OnePrimitiveIsALeafUnderTheRoot) {
  PrimitiveSet set;
  set.add_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 7, 0);
  set.build(4);
  auto hit = set.intersect({{0.25f, 0.25f, 1.0f}, {0, 0, -1}, 0.0f}, kernel::kInfinity);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->shape, 7u);
  EXPECT_FALSE(set.intersect({{2.0f, 2.0f, 1.0f}, {0, 0, -1}, 0.0f}, kernel::kInfinity));
  PrimitiveSet empty;
  empty.build();
  EXPECT_FALSE(empty.intersect({{0, 0, 1}, {0, 0, -1}, 0.0f}, kernel::kInfinity));
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
