// Renders a Scene into a linear RGB image, in tiles over worker threads.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

struct CropWindow {
  int x = 0, y = 0, width = 0, height = 0;  // in pixels of the full image
};

struct RenderOptions {
  RenderSettings settings;          // resolution, spp, integrator, max depth
  int threads = 0;                  // 0: every hardware thread
  uint32_t seed = 0;
  std::optional<CropWindow> crop;   // render (and return) only this window
  double time_budget_seconds = 0;   // > 0: add samples until this much time is spent (spp is then a cap)
  bool progress = false;            // progress bar and ETA on stderr
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

}  // namespace safegi::render
