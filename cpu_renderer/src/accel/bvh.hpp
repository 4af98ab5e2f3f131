// Bounding volume hierarchy of four- or eight-wide nodes, whose children's
// boxes one vector test checks together. Built top down by binned SAH (large
// subtrees and bin passes on parallel threads); traversal visits the nearer
// children first and stops at the first hit for shadow rays.
//
// The BVH knows only primitive bounds; the caller supplies the primitive test
// as a callable, so triangles, spheres and instances share one traversal.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "accel/lanes.hpp"
#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render::kernel {

// Runs `work(chunk, begin, end)` over `count` items in `chunks` contiguous
// chunks, chunk 0 on this thread and each other on a thread of its own.
template <class Work>
void for_each_chunk(uint32_t count, int chunks, Work&& work) {
  std::vector<std::thread> helpers;
  auto range = [&](int chunk) {
    return std::pair{static_cast<uint32_t>(uint64_t{count} * chunk / chunks),
                     static_cast<uint32_t>(uint64_t{count} * (chunk + 1) / chunks)};
  };
  for (int chunk = 1; chunk < chunks; ++chunk)
    helpers.emplace_back([&work, chunk, r = range(chunk)] { work(chunk, r.first, r.second); });
  auto [begin, end] = range(0);
  work(0, begin, end);
  for (std::thread& helper : helpers) helper.join();
}

// Passes over fewer items than this stay on one thread: below it a thread's
// start costs more than the work it takes over.
inline constexpr uint32_t kParallelMinimum = 1u << 14;

// A node's children side by side: four (two cache lines in float) or eight
// (four), aligned so that a node never straddles a cache line more.
template <int Width>
struct alignas(64) BasicWideBvhNode {
  static constexpr int kWidth = Width;
  // The children's boxes, one array per slab plane (lower[axis][child]), so
  // that each plane of all children is one vector load and one vector
  // operation (intersect_children). An empty slot holds an inverted box.
  Real lower[3][kWidth];
  Real upper[3][kWidth];
  // Interior child: its node index. Leaf child: its first leaf entry.
  uint32_t child[kWidth];
  uint16_t primitive_count[kWidth];  // 0 for an interior child or an empty slot
  // Bit i set: slot i holds a child. A ray with a NaN component passes every
  // slab test, even an empty slot's; this mask keeps it out of those.
  uint8_t occupied = 0;
  static_assert(Width <= 8, "occupied has a bit per slot");
};
// Four-wide: the GPU renderer's layout (its shader reads four children) and
// the spheres'. The CPU's triangles take eight (Bvh8): half the nodes on a
// ray's way down, each one AVX2 test where the CPU has it (traverse_avx2).
using WideBvhNode = BasicWideBvhNode<4>;

#if defined(__x86_64__) || defined(__i386__)
#define SAFEGI_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define SAFEGI_TARGET_AVX2  // no AVX2 to compile for; cpu_has_avx2() is false
#endif

// A ray prepared for slab tests.
struct TraversalRay {
  Real3 origin;
  Real3 direction;
  Real3 inverse_direction;
  int direction_is_negative[3];

  TraversalRay(Real3 o, Real3 d) : origin(o), direction(d) {
    inverse_direction = {1.0f / d.x, 1.0f / d.y, 1.0f / d.z};
    direction_is_negative[0] = inverse_direction.x < 0;
    direction_is_negative[1] = inverse_direction.y < 0;
    direction_is_negative[2] = inverse_direction.z < 0;
  }
};

template <int Width>
class BasicBvh {
 public:
  using Node = BasicWideBvhNode<Width>;
  static constexpr int kDefaultMaxLeafSize = 4;

  BasicBvh() = default;
  // Builds over `bounds[i]`, the bounds of primitive i, on up to `threads`
  // threads; the hierarchy is the same whatever the thread count.
  explicit BasicBvh(std::span<const Bounds3> bounds, int max_leaf_size = kDefaultMaxLeafSize, int threads = 1);
  // The same over `count` primitives whose bounds `bounds_of(i)` gives (called
  // once each, from the build's threads), so that no array of them is kept.
  // `batch_width`: how many primitives the caller's leaf test takes at once
  // (a power of two, 1 or 4; another is taken down to one); the SAH then
  // prices a leaf by whole batches (4 triangles cost one test).
  BasicBvh(uint32_t count, const std::function<Bounds3(uint32_t)>& bounds_of, int max_leaf_size, int threads,
           int batch_width = 1);

  // The leaves' primitives: leaf entry k is primitive order[k]. The traversal
  // names entries, not primitives, so that a caller who stores its primitives
  // in this order reads a leaf's from adjacent memory; the caller takes the
  // order once to do so.
  std::vector<uint32_t> take_primitive_order() {
    std::vector<uint32_t> order;
    order.swap(primitive_order_);
    return order;
  }
  const std::vector<Node>& nodes() const { return nodes_; }
  bool empty() const { return nodes_.empty(); }
  Bounds3 bounds() const { return bounds_; }
  size_t memory_bytes() const {
    return nodes_.capacity() * sizeof(Node) + primitive_order_.capacity() * sizeof(uint32_t);
  }

  // What a build holds per primitive beside the caller's bounds: its record,
  // its place in the order (twice, while the caller reorders its primitives)
  // and the nodes, each while built and as laid out. Nodes are counted at one
  // per Width / 2 primitives (four-wide: one per two; eight-wide: one per
  // four): the meshes of bench/scale need 0.15 four-wide and 0.035–0.056
  // eight-wide.
  static const uint64_t kPeakBytesPerPrimitive;

  // Calls `test_leaf(first, count, t_max, vector_width)` for every leaf the
  // ray reaches before `t_max` (`first` its first leaf entry, see
  // take_primitive_order, or what renumber_leaves made of it; `vector_width` a
  // std::integral_constant: how many lanes of Real the code it is compiled
  // into holds in a vector, 4 for SSE, 8 for AVX2); `test_leaf` returns true
  // on a hit and lowers t_max. With `any_hit`, returns at the first hit
  // (shadow rays).
  // `prefetch_leaf(first, count)` is called for each leaf the ray enters as
  // soon as its node is tested, so that the leaf's primitives are on their way
  // from memory while nearer children are visited.
  template <bool any_hit, class LeafTest, class LeafPrefetch>
  bool traverse(const TraversalRay& ray, Real& t_max, LeafTest&& test_leaf, LeafPrefetch&& prefetch_leaf) const {
    return traverse_inline<any_hit, 4>(ray, t_max, test_leaf, prefetch_leaf);
  }
  // The same traversal compiled for AVX2 (an eight-wide node's slab test one
  // 256-bit operation; the leaf test and the exact re-test inlined into it
  // are VEX-encoded, rounding as before: no FMA, so every result is the
  // same). Only for a CPU that has it: see cpu_has_avx2.
  template <bool any_hit, class LeafTest, class LeafPrefetch>
  SAFEGI_TARGET_AVX2 bool traverse_avx2(const TraversalRay& ray, Real& t_max, LeafTest&& test_leaf,
                                        LeafPrefetch&& prefetch_leaf) const {
    return traverse_inline<any_hit, std::min(Width, 8)>(ray, t_max, test_leaf, prefetch_leaf);
  }

  // Replaces each leaf's first entry by `renumbered(first, count)`: a caller
  // that stores a leaf's primitives in blocks of its own names the block.
  template <class Renumber>
  void renumber_leaves(Renumber&& renumbered) {
    for (Node& node : nodes_)
      for (int i = 0; i < Width; ++i)
        if (node.primitive_count[i] > 0) node.child[i] = renumbered(node.child[i], node.primitive_count[i]);
  }

 private:
  struct Record {  // a primitive in the build
    Bounds3 bounds;  // followed by a member: the binning loads each corner as four lanes
    uint32_t primitive;
    Real3 centroid() const { return bounds.centroid(); }
    Real centroid(int axis) const { return (bounds.lower[axis] + bounds.upper[axis]) * 0.5f; }
  };
  class Builder;

  // traverse and traverse_avx2's one body, inlined into each so that each
  // compiles it (and the leaf test it inlines) for its own instruction set.
  template <bool any_hit, int VectorWidth, class LeafTest, class LeafPrefetch>
  [[gnu::always_inline]] inline bool traverse_inline(const TraversalRay& ray, Real& t_max, LeafTest& test_leaf,
                                                     LeafPrefetch& prefetch_leaf) const;

  std::vector<Node> nodes_;
  std::vector<uint32_t> primitive_order_;
  Bounds3 bounds_;
};

template <int Width>
inline constexpr uint64_t BasicBvh<Width>::kPeakBytesPerPrimitive =
    sizeof(Record) + 2 * sizeof(uint32_t) + (sizeof(Node) + Width * sizeof(void*) + sizeof(Node)) * 2 / Width;

using Bvh = BasicBvh<4>;
using Bvh8 = BasicBvh<8>;

// Whether this CPU runs AVX2 code (traverse_avx2), asked of the CPU once. The
// build itself targets any x86-64, so the choice is made here, not by -march.
bool cpu_has_avx2();
// Whether the renderer traces through traverse_avx2: cpu_has_avx2(), or false
// where a test compares the SSE build of the same kernels with it.
inline bool traversal_uses_avx2 = cpu_has_avx2();

// t_max widened by 1 + 2γ(3), so that rounding in the slab test never loses a
// box the ray touches (pbrt-v3 §3.9.2).
inline constexpr Real kSlabWidening = 1 + 2 * gamma(3);

// Slab test of one box.
inline bool intersect_bounds(const Bounds3& b, const TraversalRay& ray, Real t_max) {
  const Real3& lo = b.lower;
  const Real3& hi = b.upper;
  const int* neg = ray.direction_is_negative;
  Real tx0 = ((neg[0] ? hi.x : lo.x) - ray.origin.x) * ray.inverse_direction.x;
  Real tx1 = ((neg[0] ? lo.x : hi.x) - ray.origin.x) * ray.inverse_direction.x;
  Real ty0 = ((neg[1] ? hi.y : lo.y) - ray.origin.y) * ray.inverse_direction.y;
  Real ty1 = ((neg[1] ? lo.y : hi.y) - ray.origin.y) * ray.inverse_direction.y;
  Real tz0 = ((neg[2] ? hi.z : lo.z) - ray.origin.z) * ray.inverse_direction.z;
  Real tz1 = ((neg[2] ? lo.z : hi.z) - ray.origin.z) * ray.inverse_direction.z;
  Real t_near = std::max(std::max(tx0, ty0), std::max(tz0, Real(0)));
  Real t_far = std::min(std::min(tx1 * kSlabWidening, ty1 * kSlabWidening), std::min(tz1 * kSlabWidening, t_max));
  return t_near <= t_far;
}

// Slab test of a node's children, `VectorWidth` at a time (one vector of lanes
// each plane): eight at once in AVX2 code; four at a time in SSE code, where
// GCC would take a vector of eight apart lane by lane. `t_near[i]` is where the
// ray enters child i. NaN-tolerant the way pbrt-v3 is: a 0 · ∞ term is
// ignored, because each comparison below keeps the other operand when one is NaN.
template <int VectorWidth, int Width>
inline unsigned intersect_children(const BasicWideBvhNode<Width>& node, const TraversalRay& ray, Real t_max,
                                   Real (&t_near_out)[Width]) {
  static_assert(Width % VectorWidth == 0, "whole vectors of children");
  using Lanes = typename LanesOf<VectorWidth>::Type;
  unsigned entered_bits = 0;
  for (int first = 0; first < Width; first += VectorWidth) {
    Lanes t_near = {}, t_far = Lanes{} + t_max;
    for (int axis = 0; axis < 3; ++axis) {
      const bool negative = ray.direction_is_negative[axis];
      Lanes near_plane, far_plane;
      std::memcpy(&near_plane, (negative ? node.upper[axis] : node.lower[axis]) + first, sizeof near_plane);
      std::memcpy(&far_plane, (negative ? node.lower[axis] : node.upper[axis]) + first, sizeof far_plane);
      const Real origin = ray.origin[axis], inverse = ray.inverse_direction[axis];
      Lanes t0 = (near_plane - origin) * inverse;
      Lanes t1 = (far_plane - origin) * inverse * kSlabWidening;
      t_near = t0 > t_near ? t0 : t_near;
      t_far = t1 < t_far ? t1 : t_far;
    }
    const auto entered = t_near <= t_far;
    std::memcpy(t_near_out + first, &t_near, sizeof t_near);
    entered_bits |= lane_bits(entered) << first;
  }
  return entered_bits;
}

template <int Width>
template <bool any_hit, int VectorWidth, class LeafTest, class LeafPrefetch>
bool BasicBvh<Width>::traverse_inline(const TraversalRay& ray, Real& t_max, LeafTest& test_leaf,
                                      LeafPrefetch& prefetch_leaf) const {
  if (nodes_.empty()) return false;
  struct Entry {
    Real t_near;
    uint32_t child;
    uint32_t primitive_count;  // 0: `child` is a node
  };
  // Each visit pushes at most Width - 1 entries (the nearest child is visited
  // next without a round trip through the stack), and the build is at most ~80
  // binary splits deep (SAH to depth 48, then halving by count), each node at
  // least one of them, so (Width - 1) · 86 entries suffice.
  Entry stack[(Width - 1) * 86];
  int stack_size = 0;
  Entry current{0, 0, 0};
  bool hit = false;
  for (;;) {
    if (current.primitive_count > 0) {
      if (test_leaf(current.child, current.primitive_count, t_max, std::integral_constant<int, VectorWidth>{})) {
        hit = true;
        if constexpr (any_hit) return true;
      }
    } else {
      const Node& node = nodes_[current.child];
      Real t_near[Width];
      unsigned hits = intersect_children<VectorWidth>(node, ray, t_max, t_near) & node.occupied;
      if (hits != 0) {
        auto entry = [&](int i) {
          Entry e{t_near[i], node.child[i], node.primitive_count[i]};
          if (e.primitive_count == 0) {  // fetch both of its cache lines while the others are visited
            __builtin_prefetch(&nodes_[e.child]);
            __builtin_prefetch(reinterpret_cast<const char*>(&nodes_[e.child]) + 64);
          } else {
            prefetch_leaf(e.child, e.primitive_count);
          }
          return e;
        };
        // The nearest child hit is visited next; the others are pushed, the
        // farthest lowest, so that they come off the stack nearest first.
        Entry nearest = entry(std::countr_zero(hits));
        const int first_pushed = stack_size;
        for (hits &= hits - 1; hits != 0; hits &= hits - 1) {
          Entry e = entry(std::countr_zero(hits));
          if (e.t_near < nearest.t_near) std::swap(e, nearest);
          int j = stack_size++;
          for (; j > first_pushed && stack[j - 1].t_near < e.t_near; --j) stack[j] = stack[j - 1];
          stack[j] = e;
        }
        current = nearest;
        continue;
      }
    }
    // The next pushed entry still nearer than the nearest hit so far.
    do {
      if (stack_size == 0) return hit;
      current = stack[--stack_size];
    } while (current.t_near > t_max);
  }
}

}  // namespace safegi::render::kernel
