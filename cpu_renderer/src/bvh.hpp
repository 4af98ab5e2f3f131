// Bounding volume hierarchy: binned SAH build, depth-first node layout,
// near-child-first stack traversal.
//
// The BVH knows only primitive bounds; the caller supplies the primitive test
// as a callable, so triangles, spheres and instances share one traversal.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "safegi/cpu_renderer/kernel_math.hpp"

namespace safegi::render::kernel {

struct BvhNode {
  Bounds3 bounds;
  // Leaf: index of the first primitive in `primitive_order`.
  // Interior: index of the second child (the first child is the next node).
  uint32_t offset = 0;
  uint16_t primitive_count = 0;  // 0 for interior nodes
  uint8_t split_axis = 0;
};

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

class Bvh {
 public:
  Bvh() = default;
  // Builds over `bounds[i]`, the bounds of primitive i.
  explicit Bvh(std::span<const Bounds3> bounds, int max_leaf_size = 4);

  const std::vector<uint32_t>& primitive_order() const { return primitive_order_; }
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  bool empty() const { return nodes_.empty(); }
  size_t memory_bytes() const {
    return nodes_.capacity() * sizeof(BvhNode) + primitive_order_.capacity() * sizeof(uint32_t);
  }
  Bounds3 bounds() const { return nodes_.empty() ? Bounds3{} : nodes_[0].bounds; }

  // Calls `test(primitive, t_max)` for every primitive whose leaf the ray
  // reaches before `t_max`; `test` returns true on a hit and lowers t_max.
  // With `any_hit`, returns at the first hit (shadow rays).
  template <bool any_hit, class PrimitiveTest>
  bool traverse(const TraversalRay& ray, Real& t_max, PrimitiveTest&& test) const;

 private:
  uint32_t build_recursive(std::span<const Bounds3> bounds, std::vector<Real3>& centroids,
                           uint32_t begin, uint32_t end, int max_leaf_size);

  std::vector<BvhNode> nodes_;
  std::vector<uint32_t> primitive_order_;
  int depth_ = 0;  // of the node being built
};

// Slab test; robust against NaN from 0 * inf (pbrt-v3 §3.9.2 widening of t_far).
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
  constexpr Real widen = 1 + 2 * gamma(3);
  Real t_near = std::max(std::max(tx0, ty0), std::max(tz0, Real(0)));
  Real t_far = std::min(std::min(tx1 * widen, ty1 * widen), std::min(tz1 * widen, t_max));
  return t_near <= t_far;
}

template <bool any_hit, class PrimitiveTest>
bool Bvh::traverse(const TraversalRay& ray, Real& t_max, PrimitiveTest&& test) const {
  if (nodes_.empty()) return false;
  bool hit = false;
  uint32_t stack[128];
  int stack_size = 0;
  uint32_t current = 0;
  for (;;) {
    const BvhNode& node = nodes_[current];
    if (intersect_bounds(node.bounds, ray, t_max)) {
      if (node.primitive_count > 0) {
        for (uint32_t i = 0; i < node.primitive_count; ++i) {
          if (test(primitive_order_[node.offset + i], t_max)) {
            hit = true;
            if constexpr (any_hit) return true;
          }
        }
        if (stack_size == 0) break;
        current = stack[--stack_size];
      } else if (ray.direction_is_negative[node.split_axis]) {
        stack[stack_size++] = current + 1;
        current = node.offset;
      } else {
        stack[stack_size++] = node.offset;
        current = current + 1;
      }
    } else {
      if (stack_size == 0) break;
      current = stack[--stack_size];
    }
  }
  return hit;
}

}  // namespace safegi::render::kernel
