// Tiles' results added in tile order, whichever thread finished them, so
// that sums over the film do not depend on the thread count: a tile's result
// waits until every lower index's is in. A thread waits before starting a
// tile too far ahead of the next one to add, so the results waiting stay few
// (tiles_ahead_per_thread per thread). Tiles are handed out in index order,
// so the tile next to add is already being rendered: waiting always ends.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <vector>

namespace safegi::render {

template <class Result>
class TileOrder {
 public:
  // Before each pass over the tiles: `tile_count` results will be added, with
  // indices 0 .. tile_count-1, by `threads` threads.
  void begin_pass(size_t tile_count, int threads, int tiles_ahead_per_thread) {
    std::lock_guard lock(mutex_);
    waiting_.clear();
    waiting_.resize(tile_count);
    next_to_add_ = 0;
    tiles_ahead_ = static_cast<size_t>(std::max(1, threads) * std::max(1, tiles_ahead_per_thread));
  }
  // Returns when tile `index` may start.
  void wait_for_room(size_t index) {
    std::unique_lock lock(mutex_);
    added_.wait(lock, [&] { return index < next_to_add_ + tiles_ahead_; });
  }
  // Hands tile `index`'s result to `add` once every lower index's has been (under the lock). Thread-safe.
  template <class Add>
  void add_in_order(size_t index, Result&& result, Add&& add) {
    {
      std::lock_guard lock(mutex_);
      waiting_[index] = std::move(result);
      for (; next_to_add_ < waiting_.size() && waiting_[next_to_add_]; ++next_to_add_) {
        add(*waiting_[next_to_add_]);
        waiting_[next_to_add_].reset();
      }
    }
    added_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable added_;
  std::vector<std::optional<Result>> waiting_;
  size_t next_to_add_ = 0;
  size_t tiles_ahead_ = 1;
};

}  // namespace safegi::render
