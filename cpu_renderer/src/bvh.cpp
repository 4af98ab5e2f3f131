#include "bvh.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <memory>
#include <mutex>
#include <numeric>
#include <thread>

namespace safegi::render::kernel {

namespace {

constexpr int kBinCount = 16;
// Below this depth SAH decides; deeper, splits are by count so the traversal
// stack can never overflow on degenerate input.
constexpr int kMaxSahDepth = 48;
// Relative cost of one traversal step against one primitive test.
constexpr Real kTraversalCost = 0.5f;
// Subtrees and bin passes smaller than this stay on one thread: below it a
// thread's start costs more than the work it takes over.
constexpr uint32_t kParallelMinimum = 1u << 14;
constexpr uint32_t kMaxLeafPrimitives = 0xFFFFu;  // WideBvhNode::primitive_count is 16 bits

struct Bin {
  Bounds3 bounds;
  Bounds3 centroid_bounds;
  uint32_t count = 0;
};
using AxisBins = std::array<Bin, kBinCount>;

// The two sides of a node's split, each with its box and its centroids' box
// (read off the bins, so no pass over the primitives recomputes them).
struct Side {
  Bounds3 bounds;
  Bounds3 centroid_bounds;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  Real cost = std::numeric_limits<Real>::infinity();
  Side left, right;
};

int bin_of(Real centroid, Real lower, Real scale) {
  return std::min(kBinCount - 1, static_cast<int>((centroid - lower) * scale));
}

// Runs `work(chunk, begin, end)` over `count` items in `chunks` contiguous
// chunks, chunk 0 on this thread.
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

}  // namespace

// The binary SAH tree, built into per-thread arenas; `collapse` then lays it
// out as four-wide nodes. Every decision depends only on the primitives, so
// the tree is the same on one thread or many.
class Bvh::BinaryBuilder {
 public:
  BinaryBuilder(std::span<const Bounds3> bounds, std::vector<uint32_t>& order, int max_leaf_size)
      : bounds_(bounds), order_(order), max_leaf_size_(static_cast<uint32_t>(std::max(1, max_leaf_size))) {
    centroids_.resize(bounds.size());
  }

  const BinaryNode& build(int threads) {
    const uint32_t count = static_cast<uint32_t>(bounds_.size());
    const int chunks = count >= kParallelMinimum ? threads : 1;
    std::vector<Side> chunk_sides(chunks);
    for_each_chunk(count, chunks, [&](int chunk, uint32_t begin, uint32_t end) {
      for (uint32_t i = begin; i < end; ++i) {
        centroids_[i] = bounds_[i].centroid();
        chunk_sides[chunk].bounds.extend(bounds_[i]);
        chunk_sides[chunk].centroid_bounds.extend(centroids_[i]);
      }
    });
    Side root;
    for (const Side& side : chunk_sides) {
      root.bounds.extend(side.bounds);
      root.centroid_bounds.extend(side.centroid_bounds);
    }
    return build_node(0, count, root, 0, threads, new_arena());
  }

 private:
  std::deque<BinaryNode>& new_arena() {
    std::lock_guard lock(arenas_mutex_);
    return *arenas_.emplace_back(std::make_unique<std::deque<BinaryNode>>());
  }

  // Binned SAH over the node's primitives, the binning split over `threads`
  // threads for large nodes (bins merge exactly, so the result is the same).
  Split find_split(uint32_t begin, uint32_t end, const Side& node, int threads) const {
    const uint32_t count = end - begin;
    const int chunks = count >= kParallelMinimum ? threads : 1;
    const Bounds3& centroid_bounds = node.centroid_bounds;
    std::vector<std::array<AxisBins, 3>> chunk_bins(chunks);
    for_each_chunk(count, chunks, [&](int chunk, uint32_t chunk_begin, uint32_t chunk_end) {
      for (int axis = 0; axis < 3; ++axis) {
        Real lower = centroid_bounds.lower[axis], extent = centroid_bounds.upper[axis] - lower;
        if (!(extent > 0)) continue;
        Real scale = kBinCount / extent;
        AxisBins& bins = chunk_bins[chunk][axis];
        for (uint32_t i = begin + chunk_begin; i < begin + chunk_end; ++i) {
          uint32_t primitive = order_[i];
          Bin& bin = bins[bin_of(centroids_[primitive][axis], lower, scale)];
          bin.count++;
          bin.bounds.extend(bounds_[primitive]);
          bin.centroid_bounds.extend(centroids_[primitive]);
        }
      }
    });
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(centroid_bounds.upper[axis] - centroid_bounds.lower[axis] > 0)) continue;
      AxisBins bins = chunk_bins[0][axis];
      for (int chunk = 1; chunk < chunks; ++chunk)
        for (int b = 0; b < kBinCount; ++b) {
          bins[b].count += chunk_bins[chunk][axis][b].count;
          bins[b].bounds.extend(chunk_bins[chunk][axis][b].bounds);
          bins[b].centroid_bounds.extend(chunk_bins[chunk][axis][b].centroid_bounds);
        }
      // Sweep from the right to get every right side, then from the left.
      Side right_sides[kBinCount];
      uint32_t right_count[kBinCount];
      Side right;
      uint32_t right_total = 0;
      for (int b = kBinCount - 1; b > 0; --b) {
        right.bounds.extend(bins[b].bounds);
        right.centroid_bounds.extend(bins[b].centroid_bounds);
        right_total += bins[b].count;
        right_sides[b] = right;
        right_count[b] = right_total;
      }
      Side left;
      uint32_t left_total = 0;
      for (int b = 0; b < kBinCount - 1; ++b) {
        left.bounds.extend(bins[b].bounds);
        left.centroid_bounds.extend(bins[b].centroid_bounds);
        left_total += bins[b].count;
        if (left_total == 0 || right_count[b + 1] == 0) continue;
        Real cost = left.bounds.surface_area() * left_total + right_sides[b + 1].bounds.surface_area() * right_count[b + 1];
        if (cost < best.cost) best = Split{axis, b, cost, left, right_sides[b + 1]};
      }
    }
    return best;
  }

  Side side_of(uint32_t begin, uint32_t end) const {
    Side side;
    for (uint32_t i = begin; i < end; ++i) {
      side.bounds.extend(bounds_[order_[i]]);
      side.centroid_bounds.extend(centroids_[order_[i]]);
    }
    return side;
  }

  const BinaryNode& build_node(uint32_t begin, uint32_t end, const Side& side, int depth, int threads,
                               std::deque<BinaryNode>& arena) {
    BinaryNode& node = arena.emplace_back();
    node.bounds = side.bounds;
    const uint32_t count = end - begin;
    auto make_leaf = [&]() -> const BinaryNode& {
      node.begin = begin;
      node.count = count;
      return node;
    };
    if (count <= max_leaf_size_) return make_leaf();

    uint32_t middle = begin;
    Side left, right;
    int axis = side.centroid_bounds.widest_axis();
    if (depth < kMaxSahDepth) {
      Split split = find_split(begin, end, side, threads);
      Real leaf_cost = static_cast<Real>(count);
      Real split_cost = split.axis < 0 ? leaf_cost : kTraversalCost + split.cost / side.bounds.surface_area();
      if (split.axis >= 0 && (split_cost < leaf_cost || count > kMaxLeafPrimitives)) {
        axis = split.axis;
        Real lower = side.centroid_bounds.lower[axis];
        Real scale = kBinCount / (side.centroid_bounds.upper[axis] - lower);
        auto goes_left = [&](uint32_t primitive) { return bin_of(centroids_[primitive][axis], lower, scale) <= split.bin; };
        middle = static_cast<uint32_t>(std::partition(order_.begin() + begin, order_.begin() + end, goes_left) -
                                       order_.begin());
        left = split.left;
        right = split.right;
      } else if (split.axis >= 0 || count <= kMaxLeafPrimitives) {
        return make_leaf();
      }
    }
    if (middle == begin || middle == end) {  // no SAH split: halve by count
      middle = begin + count / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                       [&](uint32_t a, uint32_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
      left = side_of(begin, middle);
      right = side_of(middle, end);
    }
    // Large subtrees split the threads between them; the left one gets its
    // own thread and arena.
    if (threads > 1 && count >= kParallelMinimum) {
      const int left_threads = threads / 2;
      const BinaryNode* left_child = nullptr;
      std::thread helper([&, left_threads] {
        left_child = &build_node(begin, middle, left, depth + 1, left_threads, new_arena());
      });
      node.children[1] = &build_node(middle, end, right, depth + 1, threads - left_threads, arena);
      helper.join();
      node.children[0] = left_child;
    } else {
      node.children[0] = &build_node(begin, middle, left, depth + 1, 1, arena);
      node.children[1] = &build_node(middle, end, right, depth + 1, 1, arena);
    }
    return node;
  }

  std::span<const Bounds3> bounds_;
  std::vector<uint32_t>& order_;
  const uint32_t max_leaf_size_;
  std::vector<Real3> centroids_;
  std::mutex arenas_mutex_;
  std::vector<std::unique_ptr<std::deque<BinaryNode>>> arenas_;
};

Bvh::Bvh(std::span<const Bounds3> bounds, int max_leaf_size, int threads) {
  if (bounds.empty()) return;
  primitive_order_.resize(bounds.size());
  std::iota(primitive_order_.begin(), primitive_order_.end(), 0u);
  BinaryBuilder builder(bounds, primitive_order_, max_leaf_size);
  const BinaryNode& root = builder.build(std::max(1, threads));
  bounds_ = root.bounds;
  if (root.leaf()) {  // the root is always a wide node: here, with one leaf child
    BinaryNode parent;
    parent.bounds = root.bounds;
    parent.children[0] = &root;
    collapse(parent);
  } else {
    collapse(root);
  }
}

// Lays out `binary` (an interior node) as a wide node: its children, each
// interior one with the largest box replaced by its own two children until four
// slots are filled; a slot left empty (a single-leaf root) gets an inverted box.
uint32_t Bvh::collapse(const BinaryNode& binary) {
  const BinaryNode* slots[WideBvhNode::kWidth] = {binary.children[0], binary.children[1]};
  int filled = binary.children[1] ? 2 : 1;
  while (filled < WideBvhNode::kWidth) {
    int widest = -1;
    for (int i = 0; i < filled; ++i)
      if (!slots[i]->leaf() && (widest < 0 || slots[i]->bounds.surface_area() > slots[widest]->bounds.surface_area()))
        widest = i;
    if (widest < 0) break;
    const BinaryNode* opened = slots[widest];
    slots[widest] = opened->children[0];
    slots[filled++] = opened->children[1];
  }
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  for (int i = 0; i < WideBvhNode::kWidth; ++i) {
    Bounds3 box = i < filled ? slots[i]->bounds : Bounds3{};  // Bounds3{} is inverted: +inf .. -inf
    for (int axis = 0; axis < 3; ++axis) {
      nodes_[index].lower[axis][i] = box.lower[axis];
      nodes_[index].upper[axis][i] = box.upper[axis];
    }
    nodes_[index].child[i] = 0;
    nodes_[index].primitive_count[i] = 0;
  }
  nodes_[index].occupied = static_cast<uint8_t>((1u << filled) - 1);
  for (int i = 0; i < filled; ++i) {
    if (slots[i]->leaf()) {
      nodes_[index].child[i] = slots[i]->begin;
      nodes_[index].primitive_count[i] = static_cast<uint16_t>(slots[i]->count);
    } else {
      uint32_t child = collapse(*slots[i]);  // may reallocate nodes_: index, not reference
      nodes_[index].child[i] = child;
    }
  }
  return index;
}

}  // namespace safegi::render::kernel
