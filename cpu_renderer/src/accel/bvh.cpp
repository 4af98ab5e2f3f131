#include "accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <condition_variable>
#include <deque>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace safegi::render::kernel {

namespace {

constexpr int kBinCount = 16;
// Below this depth SAH decides; deeper, splits are by count so the traversal
// stack can never overflow on degenerate input.
constexpr int kMaxSahDepth = 48;
// Relative cost of one traversal step against one leaf test (of one primitive,
// or of a batch: see batch_width). Measured by bench/scale over 1e4-1e6
// triangles in blocks of four: 0.5 gave 0.47-0.66x Embree's rays per
// CPU-second, 1.0 0.53-0.77x, 1.5 0.49-0.89x, 2.0 0.48-0.92x (larger leaves:
// better at 1e6, worse at 1e4); 1.5 keeps the gains at scale.
constexpr Real kTraversalCost = 1.5f;
constexpr uint32_t kMaxLeafPrimitives = 0xFFFFu;  // BasicWideBvhNode::primitive_count is 16 bits

// Binning touches every primitive's box three times per split, so a bin's box
// is kept as two Lanes4 (x, y, z and a lane nobody reads) that one SSE min and
// max extend. In the double build Lanes4 is 32 bytes, which GCC warns would
// pass differently with AVX; these helpers are inlined within this file.
#pragma GCC diagnostic ignored "-Wpsabi"

Lanes4 load_lanes(const Real3& v) {  // reads the Real after v too: the caller's struct has one
  Lanes4 lanes;
  std::memcpy(&lanes, &v, sizeof lanes);
  return lanes;
}

struct Bin {
  Lanes4 lower = Lanes4{} + kInfinity;
  Lanes4 upper = Lanes4{} - kInfinity;
  uint32_t count = 0;

  void extend(Lanes4 box_lower, Lanes4 box_upper) {
    lower = box_lower < lower ? box_lower : lower;
    upper = box_upper > upper ? box_upper : upper;
  }
  void merge(const Bin& other) {
    count += other.count;
    extend(other.lower, other.upper);
  }
  Bounds3 bounds() const {  // an empty bin's lanes are still ±inf: Bounds3{}
    Bounds3 box;
    box.lower = {lower[0], lower[1], lower[2]};
    box.upper = {upper[0], upper[1], upper[2]};
    return box;
  }
};
using AxisBins = std::array<Bin, kBinCount>;

// A node's part: its box and its centroids' box.
struct Side {
  Bounds3 bounds;
  Bounds3 centroid_bounds;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  Real cost = std::numeric_limits<Real>::infinity();
  Bounds3 left, right;  // read off the bins, so no pass over the primitives recomputes them
};

int bin_of(Real centroid, Real lower, Real scale) {
  return std::min(kBinCount - 1, static_cast<int>((centroid - lower) * scale));
}

}  // namespace

// Builds wide nodes top down: a node's range is split in two by binned
// SAH, then its widest part again, until Width parts or only leaves remain; each
// part that is not a leaf becomes a child node (large ones as tasks that any
// of the build's workers takes). Nodes go into per-worker arenas, then
// `flatten` lays them out depth first. Every decision depends only on the
// primitives, so the hierarchy is the same on one thread or many.
template <int Width>
class BasicBvh<Width>::Builder {
 public:
  Builder(uint32_t count, const std::function<Bounds3(uint32_t)>& bounds_of, std::vector<uint32_t>& order,
          int max_leaf_size, int batch_width)
      : bounds_of_(bounds_of),
        order_(order),
        max_leaf_size_(static_cast<uint32_t>(std::max(1, max_leaf_size))),
        batch_shift_(static_cast<uint32_t>(std::bit_width(static_cast<uint32_t>(std::max(1, batch_width))) - 1)) {
    records_.resize(count);
  }

  // Builds the hierarchy into `nodes` and fills `order`; returns its bounds.
  Bounds3 build(int threads, std::vector<Node>& nodes) {
    const uint32_t count = static_cast<uint32_t>(records_.size());
    const int chunks = count >= kParallelMinimum ? threads : 1;
    std::vector<Side> chunk_sides(chunks);
    for_each_chunk(count, chunks, [&](int chunk, uint32_t begin, uint32_t end) {
      for (uint32_t i = begin; i < end; ++i) {
        records_[i] = {bounds_of_(i), i};
        chunk_sides[chunk].bounds.extend(records_[i].bounds);
        chunk_sides[chunk].centroid_bounds.extend(records_[i].centroid());
      }
    });
    Range root{0, count, {}, 0};
    for (const Side& side : chunk_sides) {
      root.side.bounds.extend(side.bounds);
      root.side.centroid_bounds.extend(side.centroid_bounds);
    }
    // The root's splits bin on all threads; the subtrees it leaves go to
    // `threads` workers, this thread one of them. A set too small for any
    // task is built here alone, with no worker started.
    workers_ = count >= kParallelMinimum ? threads : 1;
    std::optional<std::pair<Range, Range>> halves = split(root, threads);
    Arena& arena = new_arena();
    const PendingNode& tree = halves ? build_node(*halves, threads, arena) : leaf_root(root, arena);
    if (workers_ > 1) {
      std::vector<std::thread> helpers;
      for (int worker = 1; worker < workers_; ++worker)
        helpers.emplace_back([this, &helper_arena = new_arena()] { work(helper_arena); });
      work(arena);
      for (std::thread& helper : helpers) helper.join();
    }
    size_t total = 0;
    for (const auto& arena : arenas_) total += arena->size();
    nodes.reserve(total);
    flatten(tree, nodes);
    for (uint32_t i = 0; i < count; ++i) order_[i] = records_[i].primitive;
    return root.side.bounds;
  }

 private:
  // A contiguous run of records: a slot of a node being built.
  struct Range {
    uint32_t begin = 0, end = 0;
    Side side;
    int depth = 0;  // in binary splits from the root
    bool leaf = false;
  };
  struct PendingNode {
    Node node;
    const PendingNode* children[Width] = {};
  };

  // Nodes in blocks that never move (parents point at them), one arena per thread.
  class Arena {
   public:
    PendingNode& emplace_back() {
      if (used_ == kBlockSize) {
        blocks_.push_back(std::make_unique<PendingNode[]>(kBlockSize));
        used_ = 0;
      }
      ++size_;
      return blocks_.back()[used_++];
    }
    size_t size() const { return size_; }

   private:
    static constexpr size_t kBlockSize = 1024;
    std::vector<std::unique_ptr<PendingNode[]>> blocks_;
    size_t used_ = kBlockSize, size_ = 0;
  };

  Arena& new_arena() {
    std::lock_guard lock(arenas_mutex_);
    return *arenas_.emplace_back(std::make_unique<Arena>());
  }

  // Binned SAH over the node's primitives, the binning split over `threads`
  // threads for large nodes (bins merge exactly, so the result is the same).
  Split find_split(uint32_t begin, uint32_t end, const Side& node, int threads) const {
    const uint32_t count = end - begin;
    const int chunks = count >= kParallelMinimum ? threads : 1;
    const Bounds3& centroid_bounds = node.centroid_bounds;
    // One chunk's bins live on the stack: most splits are of small nodes, and
    // an allocation each would cost more than their binning.
    std::array<AxisBins, 3> only_bins;
    std::vector<std::array<AxisBins, 3>> more_bins(chunks > 1 ? chunks : 0);
    auto chunk_bins = [&](int chunk) -> std::array<AxisBins, 3>& {
      return chunks > 1 ? more_bins[chunk] : only_bins;
    };
    // Every flat axis bins into bin 0 (scale 0) and is skipped below.
    Real lower[3], scale[3];
    for (int axis = 0; axis < 3; ++axis) {
      lower[axis] = centroid_bounds.lower[axis];
      Real extent = centroid_bounds.upper[axis] - lower[axis];
      scale[axis] = extent > 0 ? kBinCount / extent : 0;
    }
    for_each_chunk(count, chunks, [&](int chunk, uint32_t chunk_begin, uint32_t chunk_end) {
      std::array<AxisBins, 3>& bins = chunk_bins(chunk);
      for (uint32_t i = begin + chunk_begin; i < begin + chunk_end; ++i) {
        const Record& record = records_[i];
        // bounds.upper is followed by the primitive index, bounds.lower by upper.
        const Lanes4 box_lower = load_lanes(record.bounds.lower), box_upper = load_lanes(record.bounds.upper);
        for (int axis = 0; axis < 3; ++axis) {
          Bin& bin = bins[axis][bin_of(record.centroid(axis), lower[axis], scale[axis])];
          bin.count++;
          bin.extend(box_lower, box_upper);
        }
      }
    });
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(centroid_bounds.upper[axis] - centroid_bounds.lower[axis] > 0)) continue;
      AxisBins& bins = chunk_bins(0)[axis];  // the other chunks' added in place
      for (int chunk = 1; chunk < chunks; ++chunk)
        for (int b = 0; b < kBinCount; ++b) bins[b].merge(chunk_bins(chunk)[axis][b]);
      // Sweep from the right to get every right side, then from the left.
      Bounds3 right_bounds[kBinCount];
      uint32_t right_count[kBinCount];
      Bounds3 right;
      uint32_t right_total = 0;
      for (int b = kBinCount - 1; b > 0; --b) {
        right.extend(bins[b].bounds());
        right_total += bins[b].count;
        right_bounds[b] = right;
        right_count[b] = right_total;
      }
      Bounds3 left;
      uint32_t left_total = 0;
      for (int b = 0; b < kBinCount - 1; ++b) {
        left.extend(bins[b].bounds());
        left_total += bins[b].count;
        if (left_total == 0 || right_count[b + 1] == 0) continue;
        Real cost = left.surface_area() * batches(left_total) +
                    right_bounds[b + 1].surface_area() * batches(right_count[b + 1]);
        if (cost < best.cost) best = Split{axis, b, cost, left, right_bounds[b + 1]};
      }
    }
    return best;
  }

  // The leaf tests `count` primitives take (a shift: the SAH sweep asks twice per bin).
  Real batches(uint32_t count) const {
    return static_cast<Real>((count + (uint32_t{1} << batch_shift_) - 1) >> batch_shift_);
  }

  Side side_of(uint32_t begin, uint32_t end) const {
    Side side;
    for (uint32_t i = begin; i < end; ++i) {
      side.bounds.extend(records_[i].bounds);
      side.centroid_bounds.extend(records_[i].centroid());
    }
    return side;
  }

  // Splits `range` in two, or says it is a leaf (nullopt): by SAH above
  // kMaxSahDepth, by count below it or where SAH finds no split.
  std::optional<std::pair<Range, Range>> split(const Range& range, int threads) {
    const uint32_t begin = range.begin, end = range.end, count = end - begin;
    if (count <= max_leaf_size_) return std::nullopt;
    uint32_t middle = begin;
    Range left{begin, 0, {}, range.depth + 1}, right{0, end, {}, range.depth + 1};
    int axis = range.side.centroid_bounds.widest_axis();
    if (range.depth < kMaxSahDepth) {
      Split split = find_split(begin, end, range.side, threads);
      Real leaf_cost = batches(count);
      Real split_cost = split.axis < 0 ? leaf_cost : kTraversalCost + split.cost / range.side.bounds.surface_area();
      if (split.axis >= 0 && (split_cost < leaf_cost || count > kMaxLeafPrimitives)) {
        axis = split.axis;
        Real lower = range.side.centroid_bounds.lower[axis];
        Real scale = kBinCount / (range.side.centroid_bounds.upper[axis] - lower);
        auto goes_left = [&](const Record& record) { return bin_of(record.centroid(axis), lower, scale) <= split.bin; };
        // The boxes come from the bins; the centroids' boxes are gathered as the records move.
        uint32_t i = begin, j = end;
        for (;;) {
          for (; i < j && goes_left(records_[i]); ++i) left.side.centroid_bounds.extend(records_[i].centroid());
          for (; i < j && !goes_left(records_[j - 1]); --j)
            right.side.centroid_bounds.extend(records_[j - 1].centroid());
          if (i == j) break;
          std::swap(records_[i], records_[j - 1]);
        }
        middle = i;
        left.side.bounds = split.left;
        right.side.bounds = split.right;
      } else if (split.axis >= 0 || count <= kMaxLeafPrimitives) {
        return std::nullopt;
      }
    }
    if (middle == begin || middle == end) {  // no SAH split: halve by count
      middle = begin + count / 2;
      std::nth_element(records_.begin() + begin, records_.begin() + middle, records_.begin() + end,
                       [&](const Record& a, const Record& b) { return a.centroid(axis) < b.centroid(axis); });
      left.side = side_of(begin, middle);
      right.side = side_of(middle, end);
    }
    left.end = middle;
    right.begin = middle;
    return std::pair{left, right};
  }

  // A node of the first `filled` slots: boxes, leaf ranges, the occupied
  // mask; interior children are linked later.
  static PendingNode& lay_out(const Range* slots, int filled, Arena& arena) {
    PendingNode& pending = arena.emplace_back();
    Node& node = pending.node;
    for (int i = 0; i < Width; ++i) {
      Bounds3 box = i < filled ? slots[i].side.bounds : Bounds3{};  // Bounds3{} is inverted: +inf .. -inf
      for (int axis = 0; axis < 3; ++axis) {
        node.lower[axis][i] = box.lower[axis];
        node.upper[axis][i] = box.upper[axis];
      }
      const bool leaf = i < filled && slots[i].leaf;
      node.child[i] = leaf ? slots[i].begin : 0;
      node.primitive_count[i] = leaf ? static_cast<uint16_t>(slots[i].end - slots[i].begin) : 0;
    }
    node.occupied = static_cast<uint8_t>((1u << filled) - 1);
    return pending;
  }

  // Traversal always starts at a node: a set small enough for one leaf gets a
  // node with that leaf alone.
  static const PendingNode& leaf_root(Range root, Arena& arena) {
    root.leaf = true;
    return lay_out(&root, 1, arena);
  }

  // A node whose range splits into `halves`.
  const PendingNode& build_node(const std::pair<Range, Range>& halves, int threads, Arena& arena) {
    Range slots[Width] = {halves.first, halves.second};
    std::optional<std::pair<Range, Range>> slot_halves[Width];
    int filled = 2;
    // Every slot's split is found once: a slot opened here gives way to its
    // halves; one left when the node is full passes them to its own node.
    auto settle = [&](int i) {
      if (!slots[i].leaf && !slot_halves[i] && !(slot_halves[i] = split(slots[i], threads))) slots[i].leaf = true;
    };
    for (;;) {
      int widest = -1;
      for (int i = 0; i < filled; ++i) {
        settle(i);
        if (!slots[i].leaf &&
            (widest < 0 || slots[i].side.bounds.surface_area() > slots[widest].side.bounds.surface_area()))
          widest = i;
      }
      if (widest < 0 || filled == Width) break;
      std::pair<Range, Range> opened = *slot_halves[widest];
      slots[widest] = opened.first;
      slot_halves[widest].reset();
      slots[filled++] = opened.second;
    }
    PendingNode& pending = lay_out(slots, filled, arena);
    build_children(slots, slot_halves, filled, pending, arena);
    return pending;
  }

  // The interior slots' nodes. Large ones become tasks for the build's
  // workers when it has more than one; the rest are built here, on one thread.
  void build_children(const Range (&slots)[Width], const std::optional<std::pair<Range, Range>> (&slot_halves)[Width],
                      int filled,
                      PendingNode& pending, Arena& arena) {
    for (int i = 0; i < filled; ++i) {
      if (slots[i].leaf) continue;
      if (workers_ > 1 && slots[i].end - slots[i].begin >= kParallelMinimum) {
        std::lock_guard lock(tasks_mutex_);
        tasks_.push_back({*slot_halves[i], &pending.children[i]});
        task_added_.notify_one();
      } else {
        pending.children[i] = &build_node(*slot_halves[i], 1, arena);
      }
    }
  }

  // A worker: builds queued subtrees (each into this worker's arena) until the
  // queue is empty and no other worker can add to it.
  void work(Arena& arena) {
    std::unique_lock lock(tasks_mutex_);
    for (;;) {
      task_added_.wait(lock, [&] { return !tasks_.empty() || busy_ == 0; });
      if (tasks_.empty()) {
        task_added_.notify_all();  // nothing left and nobody working: the others stop too
        return;
      }
      Task task = tasks_.front();
      tasks_.pop_front();
      ++busy_;
      lock.unlock();
      *task.slot = &build_node(task.halves, 1, arena);
      lock.lock();
      --busy_;
    }
  }

  static uint32_t flatten(const PendingNode& pending, std::vector<Node>& nodes) {
    const uint32_t index = static_cast<uint32_t>(nodes.size());
    nodes.push_back(pending.node);
    for (int i = 0; i < Width; ++i)
      if (pending.children[i]) {
        uint32_t child = flatten(*pending.children[i], nodes);  // may reallocate nodes: index, not reference
        nodes[index].child[i] = child;
      }
    return index;
  }

  const std::function<Bounds3(uint32_t)>& bounds_of_;
  std::vector<uint32_t>& order_;
  const uint32_t max_leaf_size_;
  const uint32_t batch_shift_;  // log2 of the batch width (a power of two, see Bvh's constructor)
  // The primitives as the build moves them: their partitions are contiguous,
  // so every pass over a node's primitives reads memory in order.
  std::vector<Record> records_;
  std::mutex arenas_mutex_;
  std::vector<std::unique_ptr<Arena>> arenas_;

  // Subtrees waiting for a worker, each with the slot that will point at it.
  struct Task {
    std::pair<Range, Range> halves;
    const PendingNode** slot;
  };
  int workers_ = 1;
  std::mutex tasks_mutex_;
  std::condition_variable task_added_;
  std::deque<Task> tasks_;
  int busy_ = 0;  // workers building a task
};

template <int Width>
BasicBvh<Width>::BasicBvh(std::span<const Bounds3> bounds, int max_leaf_size, int threads)
    : BasicBvh(static_cast<uint32_t>(bounds.size()), [&](uint32_t i) { return bounds[i]; }, max_leaf_size, threads) {}

template <int Width>
BasicBvh<Width>::BasicBvh(uint32_t count, const std::function<Bounds3(uint32_t)>& bounds_of, int max_leaf_size,
                          int threads, int batch_width) {
  if (count == 0) return;
  primitive_order_.resize(count);
  Builder builder(count, bounds_of, primitive_order_, max_leaf_size, batch_width);
  bounds_ = builder.build(std::max(1, threads), nodes_);
}

template class BasicBvh<4>;
template class BasicBvh<8>;

bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  // __builtin_cpu_init first: this may run from a static initialiser, before
  // the one that sets up __builtin_cpu_supports.
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
#else
  return false;
#endif
}

}  // namespace safegi::render::kernel
