// What the whole-render tests share: rendering a scene given as JSON text, the
// estimator knobs every physics test must hold under, and the mean of an
// image with its standard error.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render::test_support {

inline constexpr double kPiD = std::numbers::pi;

// Estimator knobs of the speed/accuracy study; each physics test must hold under every one.
struct Knobs {
  const char* name;
  std::function<void(RenderSettings&)> apply;
};
inline const std::vector<Knobs>& estimator_knobs() {
  static const std::vector<Knobs> knobs = {
      {"defaults", [](RenderSettings&) {}},
      {"mis off", [](RenderSettings& s) { s.mis = false; }},
      {"4 light samples", [](RenderSettings& s) { s.light_samples = 4; }},
      {"mis off, 3 light samples", [](RenderSettings& s) { s.mis = false, s.light_samples = 3; }},
      {"roulette from depth 0", [](RenderSettings& s) { s.russian_roulette_depth = 0; }},
      {"lights chosen uniformly", [](RenderSettings& s) { s.light_strategy = LightStrategy::uniform; }},
      {"lights chosen by voxel", [](RenderSettings& s) { s.light_strategy = LightStrategy::spatial; }},
      {"every light, 2 rounds", [](RenderSettings& s) { s.light_strategy = LightStrategy::all, s.light_samples = 2; }},
  };
  return knobs;
}

inline Image render_scene(const Scene& scene, int spp, int threads = 2, std::optional<CropWindow> crop = std::nullopt,
                          const std::function<void(RenderSettings&)>& adjust = {}) {
  RenderOptions options;
  options.settings = scene.settings;
  options.settings.spp = spp;
  if (adjust) adjust(options.settings);
  options.threads = threads;
  options.crop = crop;
  RenderStats stats;
  Image image = render(scene, options, &stats);
  EXPECT_EQ(stats.invalid_samples, 0u);
  for (float v : image.rgb) EXPECT_TRUE(std::isfinite(v));
  return image;
}

// `base_directory`: where relative mesh and image paths of the scene resolve.
inline Image render_text(const std::string& json, int spp, int threads = 2, std::optional<CropWindow> crop = std::nullopt,
                         const std::function<void(RenderSettings&)>& adjust = {},
                         const std::filesystem::path& base_directory = SAFEGI_SCENES_DIR) {
  return render_scene(parse_scene(json, "test.json", base_directory), spp, threads, crop, adjust);
}

// The mean of radiance(x, z) over the footprint of pixel (px, py) on the plane
// y = 0, seen straight down from `camera_height` with a square image of `size`
// pixels whose half-width at unit distance is `half` (x = h·sx, z = -h·sy).
template <class Radiance>
inline double footprint_average(int px, int py, int size, double half, double camera_height, Radiance radiance) {
  double sum = 0;
  constexpr int kSub = 16;
  for (int j = 0; j < kSub; ++j)
    for (int i = 0; i < kSub; ++i) {
      double sx = (2 * (px + (i + 0.5) / kSub) / size - 1) * half;
      double sy = (1 - 2 * (py + (j + 0.5) / kSub) / size) * half;
      sum += radiance(camera_height * sx, -camera_height * sy);
    }
  return sum / (kSub * kSub);
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Mean and standard error of the mean of one channel over all pixels.
struct Estimate {
  double mean, standard_error;
};
inline Estimate channel_estimate(const Image& image, int channel) {
  double sum = 0, sum2 = 0;
  size_t n = static_cast<size_t>(image.width) * image.height;
  for (size_t i = 0; i < n; ++i) {
    double v = image.rgb[3 * i + channel];
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / n;
  double variance = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(variance / n)};
}

}  // namespace safegi::render::test_support
