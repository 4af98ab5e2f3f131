#include "distributed/distributed.hpp"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <safegi/diagnostics/exit_status.hpp>
#include <safegi/diagnostics/printable.hpp>

namespace safegi::render {

namespace {

// Thrown by render() on every rank when a rank's setup failed; rank 0 has
// printed the message already.
struct SetupFailedElsewhere : std::runtime_error {
  SetupFailedElsewhere() : std::runtime_error("a rank's setup failed") {}
};

// Calls f(tile) for every tile of `rank` (every size-th one, as RenderPartition says).
template <class F>
void for_each_tile_of(const std::vector<PixelRect>& tiles, int rank, int size, F f) {
  for (size_t t = rank; t < tiles.size(); t += size) f(tiles[t]);
}

size_t floats_per_row(const PixelRect& tile) { return 3 * static_cast<size_t>(tile.x1 - tile.x0); }

}  // namespace

// The render loop's hooks over the communicator: rank 0 decides how a
// time-budgeted render goes on, from the slowest rank's pass time.
class DistributedSession::Partition final : public RenderPartition {
 public:
  explicit Partition(DistributedSession& session) : session_(session) {}
  int part() const override { return session_.rank(); }
  int parts() const override { return session_.ranks(); }
  double slowest_pass_seconds(double seconds) override {
    session_.test_fault_point();
    session_.communicator_.wait_for_every_rank();
    return session_.communicator_.max_to_first(seconds);
  }
  int next_pass_spp_of_first(int next_pass_spp) override {
    return session_.communicator_.broadcast_from_first(next_pass_spp);
  }
  void sum_to_first(std::vector<double>& values) override {
    session_.communicator_.wait_for_every_rank();
    session_.communicator_.sum_to_first(values.data(), values.size());
  }

 private:
  DistributedSession& session_;
};

DistributedSession::DistributedSession(int& argc, char**& argv) : communicator_(argc, argv) {
  const char* fault = std::getenv("SAFEGI_RENDER_TEST_FAULT");
  if (!fault || !*fault) return;
  std::cmatch match;
  if (std::regex_match(fault, match, std::regex(R"((setup|throw|kill):(\d{1,6}))"))) {
    fault_kind_ = match[1];
    fault_rank_ = std::stoi(match[2]);
  } else {
    fault_error_ = std::string("SAFEGI_RENDER_TEST_FAULT: expected setup:RANK, throw:RANK or kill:RANK, got '") +
                   fault + "'";
  }
}

namespace {

// A message ending in a newline is a whole diagnostic already ("scene.pbrt:3:7:
// error: ..." with its source line: the pbrt importer's), printed as it is.
bool is_diagnostic(const std::string& message) { return !message.empty() && message.back() == '\n'; }
void print_error(const std::string& message) { std::fputs(error_report(message).c_str(), stderr); }

}  // namespace

void DistributedSession::agree_setup(const std::string* error) {
  std::string message = error ? *error : fault_error_;
  if (message.empty() && fault_kind_ == "setup" && fault_rank_ == rank())
    message = "test fault: rank " + std::to_string(rank()) + "'s setup fails";
  const bool failed = !message.empty();
  communicator_.wait_for_every_rank();  // some load the scene faster than others
  int first_failed = communicator_.min_over_ranks(failed ? rank() : ranks());
  if (first_failed == ranks()) return;
  int failures = communicator_.sum_over_ranks(failed ? 1 : 0);
  communicator_.broadcast(message, first_failed);
  if (is_root()) {
    // When every rank fails (the same scene file everywhere), the message is
    // the single process's; otherwise it says which rank failed first.
    if (failures == ranks())
      print_error(message);
    else {
      const bool whole = is_diagnostic(message);
      std::fprintf(stderr, "error: rank %d of %d: %s%s", first_failed, ranks(), escape_unprintable(message, whole).c_str(),
                   whole ? "" : "\n");
    }
  }
  // Called from render(): no rank renders (report_error() returns quietly).
  if (!error) throw SetupFailedElsewhere();
}

void DistributedSession::test_fault_point() {
  if (fault_rank_ != rank()) return;
  if (fault_kind_ == "throw")
    throw std::runtime_error("test fault: rank " + std::to_string(rank()) + " throws while rendering");
  if (fault_kind_ == "kill") {
    std::fprintf(stderr, "test fault: rank %d kills itself while rendering\n", rank());
    std::fflush(stderr);
    std::raise(SIGKILL);
  }
}

int DistributedSession::default_threads() const {
  // The CPUs this rank may run on, shared with the other ranks on the node
  // (all of them when the launcher does not bind ranks to cores).
  cpu_set_t cpus;
  int available = sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus)
                                                                : static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, available / std::max(1, communicator_.ranks_on_this_node()));
}

Image DistributedSession::render(const Scene& scene, RenderOptions options, RenderStats* stats) {
  agree_setup(nullptr);
  phase_ = Phase::rendering;
  if (ranks() == 1) {
    Image image = safegi::render::render(scene, options, stats);
    phase_ = Phase::reporting;
    return image;
  }

  auto start = std::chrono::steady_clock::now();
  Partition partition(*this);
  options.partition = &partition;
  options.progress = options.progress && is_root();
  if (options.threads == 0) options.threads = default_threads();
  RenderStats local;
  Image image = safegi::render::render(scene, options, &local);
  test_fault_point();
  communicator_.wait_for_every_rank();
  // Splatted or bidirectional, rank 0's image is whole already (the ranks' sums were added in render()).
  Image whole = sums_on_first_process(options.settings) ? (is_root() ? std::move(image) : Image{})
                                                        : gather_on_first(std::move(image));

  uint64_t totals[] = {local.camera_rays, local.extension_rays, local.shadow_rays, local.invalid_samples,
                       static_cast<uint64_t>(local.threads)};
  communicator_.sum_to_first(totals, 5);
  // Every rank stops at the same pass (rank 0 decides), so all took the same
  // number of samples; the lowest and the highest count prove it.
  int fewest = communicator_.min_over_ranks(local.samples_per_pixel);
  int most = -communicator_.min_over_ranks(-local.samples_per_pixel);
  phase_ = Phase::reporting;
  if (fewest != most)  // on every rank; rank 0 prints it
    throw std::logic_error("internal: the ranks rendered " + std::to_string(fewest) + " to " + std::to_string(most) +
                           " samples per pixel");
  if (!is_root()) return whole;
  if (stats) {
    *stats = local;
    stats->camera_rays = totals[0];
    stats->extension_rays = totals[1];
    stats->shadow_rays = totals[2];
    stats->invalid_samples = totals[3];
    stats->threads = static_cast<int>(totals[4]);
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return whole;
}

// Rank 0's image gets every other rank's tiles, copied: no pixel is added to
// another, so the pixels are the bits their own rank computed.
Image DistributedSession::gather_on_first(Image image) {
  std::vector<PixelRect> tiles = render_tiles(image.width, image.height);
  const size_t width = image.width;
  auto row_begin = [width](const PixelRect& tile, int y) { return 3 * (y * width + tile.x0); };
  if (!is_root()) {
    std::vector<float> mine;
    for_each_tile_of(tiles, rank(), ranks(), [&](const PixelRect& tile) {
      for (int y = tile.y0; y < tile.y1; ++y) {
        auto row = image.rgb.begin() + row_begin(tile, y);
        mine.insert(mine.end(), row, row + floats_per_row(tile));
      }
    });
    communicator_.send(mine.data(), mine.size(), 0);
    return Image{};
  }
  Image whole = std::move(image);
  std::vector<float> theirs;
  for (int from = 1; from < ranks(); ++from) {
    size_t count = 0;
    for_each_tile_of(tiles, from, ranks(),
                     [&](const PixelRect& tile) { count += floats_per_row(tile) * (tile.y1 - tile.y0); });
    theirs.resize(count);
    communicator_.receive(theirs.data(), count, from);
    const float* next = theirs.data();
    for_each_tile_of(tiles, from, ranks(), [&](const PixelRect& tile) {
      for (int y = tile.y0; y < tile.y1; ++y, next += floats_per_row(tile))
        std::copy(next, next + floats_per_row(tile), whole.rgb.begin() + row_begin(tile, y));
    });
  }
  return whole;
}

int DistributedSession::report_error(const std::exception& error) {
  if (dynamic_cast<const SetupFailedElsewhere*>(&error)) return kExitInputError;
  const int status = dynamic_cast<const CommandLineError*>(&error) ? kExitUsage : kExitInputError;
  switch (phase_) {
    case Phase::setup: {
      std::string message = error.what();
      agree_setup(&message);
      return status;
    }
    case Phase::rendering:
      if (ranks() > 1) {
        // The other ranks wait in a collective for this one: end the job.
        std::fprintf(stderr, "error: rank %d of %d: %s\n", rank(), ranks(), escape_unprintable(error.what()).c_str());
        std::fflush(stderr);
        communicator_.abort(1);
      }
      break;
    case Phase::reporting:
      if (!is_root()) return status;  // rank 0 reports for all
      break;
  }
  print_error(error.what());
  return status;
}

}  // namespace safegi::render
