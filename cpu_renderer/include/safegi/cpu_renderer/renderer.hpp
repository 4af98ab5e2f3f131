// Renders a Scene into a linear RGB image, in tiles over worker threads.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

struct CropWindow {
  int x = 0, y = 0, width = 0, height = 0;  // in pixels of the full image
};

struct PixelRect {
  int x0, y0, x1, y1;  // the pixels [x0, x1) × [y0, y1)
};

// The 16×16 tiles of a width × height window, row by row, relative to its
// corner: the units of work the renderer hands to its threads (and a
// distributed render to its processes).
std::vector<PixelRect> render_tiles(int width, int height);

// One process's share of a render split over several processes
// (cpu_renderer/src/distributed/distributed.hpp). The process renders the tiles t with
// t % parts() == part(), each pixel with all its samples, so every pixel's sum
// adds the same samples in the same order as a single process would; a
// time-budgeted render's pass decisions are taken by process 0 for all.
class RenderPartition {
 public:
  virtual ~RenderPartition() = default;
  virtual int part() const = 0;
  virtual int parts() const = 0;
  // Collective, after each time-budgeted pass: this process's seconds for the
  // pass in, the slowest process's out (on process 0; elsewhere unspecified).
  virtual double slowest_pass_seconds(double seconds) = 0;
  // Collective: process 0's decision on every process (samples per pixel of
  // the next pass; 0: stop here).
  virtual int next_pass_spp_of_first(int next_pass_spp) = 0;
  // Collective, at the end of a render whose samples splat (see
  // splats_samples: a sample adds to its neighbours' pixels, which other
  // processes may own): the sum of every process's `values`, element by
  // element, into process 0's.
  virtual void sum_to_first(std::vector<double>& values) = 0;
};

// Whether a render with this filter splats each sample over the pixels within
// the filter's radius (PixelFilterMode::splat; a plain one-pixel box never needs to).
bool splats_samples(const PixelFilter& filter);

// Whether a render split over processes ends with the whole image on process
// 0, every process's sums added there (RenderPartition::sum_to_first):
// splatted samples, and the bidirectional path tracer, whose light tracing
// lands on any process's pixels. Otherwise process 0 gathers the others' tiles.
bool sums_on_first_process(const RenderSettings& settings);

struct RenderOptions {
  RenderSettings settings;          // resolution, spp, integrator, max depth
  int threads = 0;                  // 0: every hardware thread
  uint32_t seed = 0;
  std::optional<CropWindow> crop;   // render (and return) only this window
  double time_budget_seconds = 0;   // > 0: add samples until this much time is spent (spp is then a cap)
  bool progress = false;            // progress bar and ETA on stderr
  RenderPartition* partition = nullptr;  // null: this process renders every tile
};

struct RenderStats {
  uint64_t camera_rays = 0;
  uint64_t extension_rays = 0;
  uint64_t shadow_rays = 0;
  uint64_t invalid_samples = 0;  // NaN or infinite radiance, dropped
  int samples_per_pixel = 0;
  int threads = 0;     // worker threads actually used
  double seconds = 0;  // wall-clock time of the render
  uint64_t total_rays() const { return camera_rays + extension_rays + shadow_rays; }
};

Image render(const Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr);

// A command-line value the programs refuse (exit status kExitUsage, not the
// scene's kExitInputError); what() is the whole message.
class CommandLineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImageSize {
  int width = 0, height = 0;
};

// `--resolution`'s "WIDTHxHEIGHT", each side 1 to kMaxImageSide; throws
// CommandLineError naming `option` and what is wrong (the syntax, or the limit).
ImageSize parse_resolution(const std::string& text, const std::string& option = "--resolution");

}  // namespace safegi::render
