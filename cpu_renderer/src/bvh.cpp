#include "bvh.hpp"

#include <algorithm>
#include <numeric>

namespace safegi::render::kernel {

namespace {

constexpr int kBinCount = 16;
// Below this depth SAH decides; deeper, splits are by count so the traversal
// stack (128 entries) can never overflow on degenerate input.
constexpr int kMaxSahDepth = 48;
// Relative cost of one traversal step against one primitive test.
constexpr Real kTraversalCost = 0.5f;

struct Bin {
  Bounds3 bounds;
  uint32_t count = 0;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  Real cost = std::numeric_limits<Real>::infinity();
};

Split find_sah_split(std::span<const Bounds3> bounds, const std::vector<Real3>& centroids,
                     std::span<const uint32_t> primitives, const Bounds3& centroid_bounds) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    Real lo = centroid_bounds.lower[axis];
    Real extent = centroid_bounds.upper[axis] - lo;
    if (!(extent > 0)) continue;
    Bin bins[kBinCount];
    Real scale = kBinCount / extent;
    for (uint32_t primitive : primitives) {
      int b = std::min(kBinCount - 1, static_cast<int>((centroids[primitive][axis] - lo) * scale));
      bins[b].count++;
      bins[b].bounds.extend(bounds[primitive]);
    }
    // Sweep from the right to get the cost of every right side, then from the left.
    Real right_area[kBinCount];
    uint32_t right_count[kBinCount];
    Bounds3 right;
    uint32_t count = 0;
    for (int b = kBinCount - 1; b > 0; --b) {
      right.extend(bins[b].bounds);
      count += bins[b].count;
      right_area[b] = right.surface_area();
      right_count[b] = count;
    }
    Bounds3 left;
    count = 0;
    for (int b = 0; b < kBinCount - 1; ++b) {
      left.extend(bins[b].bounds);
      count += bins[b].count;
      if (count == 0 || right_count[b + 1] == 0) continue;
      Real cost = left.surface_area() * count + right_area[b + 1] * right_count[b + 1];
      if (cost < best.cost) best = Split{axis, b, cost};
    }
  }
  return best;
}

}  // namespace

Bvh::Bvh(std::span<const Bounds3> bounds, int max_leaf_size) {
  if (bounds.empty()) return;
  primitive_order_.resize(bounds.size());
  std::iota(primitive_order_.begin(), primitive_order_.end(), 0u);
  std::vector<Real3> centroids(bounds.size());
  for (size_t i = 0; i < bounds.size(); ++i) centroids[i] = bounds[i].centroid();
  nodes_.reserve(2 * bounds.size());
  depth_ = 0;
  build_recursive(bounds, centroids, 0, static_cast<uint32_t>(bounds.size()), max_leaf_size);
}

uint32_t Bvh::build_recursive(std::span<const Bounds3> bounds, std::vector<Real3>& centroids,
                              uint32_t begin, uint32_t end, int max_leaf_size) {
  uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Bounds3 node_bounds, centroid_bounds;
  for (uint32_t i = begin; i < end; ++i) {
    node_bounds.extend(bounds[primitive_order_[i]]);
    centroid_bounds.extend(centroids[primitive_order_[i]]);
  }
  nodes_[index].bounds = node_bounds;
  uint32_t count = end - begin;
  auto make_leaf = [&] {
    nodes_[index].offset = begin;
    nodes_[index].primitive_count = static_cast<uint16_t>(count);
    return index;
  };
  if (count <= static_cast<uint32_t>(max_leaf_size)) return make_leaf();

  std::span<uint32_t> primitives(primitive_order_.data() + begin, count);
  uint32_t middle = begin;
  int axis = centroid_bounds.widest_axis();
  if (depth_ < kMaxSahDepth) {
    Split split = find_sah_split(bounds, centroids, primitives, centroid_bounds);
    Real leaf_cost = static_cast<Real>(count);
    Real split_cost = split.axis < 0 ? leaf_cost
                                      : kTraversalCost + split.cost / node_bounds.surface_area();
    if (split.axis >= 0 && (split_cost < leaf_cost || count > 0xFFFFu)) {
      axis = split.axis;
      Real lo = centroid_bounds.lower[axis];
      Real scale = kBinCount / (centroid_bounds.upper[axis] - lo);
      auto goes_left = [&](uint32_t primitive) {
        int b = std::min(kBinCount - 1, static_cast<int>((centroids[primitive][axis] - lo) * scale));
        return b <= split.bin;
      };
      middle = begin + static_cast<uint32_t>(std::partition(primitives.begin(), primitives.end(), goes_left) -
                                             primitives.begin());
    } else if (split.axis >= 0 || count <= 0xFFFFu) {
      return make_leaf();
    }
  }
  if (middle == begin || middle == end) {  // no SAH split: halve by count
    middle = begin + count / 2;
    std::nth_element(primitive_order_.begin() + begin, primitive_order_.begin() + middle,
                     primitive_order_.begin() + end, [&](uint32_t a, uint32_t b) {
                       return centroids[a][axis] < centroids[b][axis];
                     });
  }
  nodes_[index].split_axis = static_cast<uint8_t>(axis);
  ++depth_;
  build_recursive(bounds, centroids, begin, middle, max_leaf_size);
  uint32_t second = build_recursive(bounds, centroids, middle, end, max_leaf_size);
  --depth_;
  nodes_[index].offset = second;
  return index;
}

}  // namespace safegi::render::kernel
