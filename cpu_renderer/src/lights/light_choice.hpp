// Which light a shadow ray goes to (pbrt-v3's LightDistribution): a discrete
// distribution over the scene's lights, held as its running sums, either the
// same at every shading point (by power, or uniform) or the one of the shading
// point's voxel of the scene (spatial).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "safegi/cpu_renderer/kernel_math.hpp"
#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

// Running sums of a distribution over lights, normalised (the last is exactly
// 1); all-zero or non-finite weights give the uniform distribution.
std::vector<Real> light_cdf(std::span<const double> weights);

struct ChosenLight {
  uint32_t index = 0;
  Real probability = 0;
  Real u_within = 0;  // the choosing number, rescaled to [0, 1) within the chosen light's share
};
ChosenLight choose_light(std::span<const Real> cdf, Real u);
Real light_probability(std::span<const Real> cdf, uint32_t light);

// pbrt-v3's SpatialLightDistribution: the scene's box cut into voxels (64
// along its longest side, fewer for thousands of lights), each voxel's distribution made the first time a
// shading point in it asks, from each light's estimated contribution at 128
// points in the voxel (no visibility, no surface), every light kept at no less
// than a thousandth of the mean so that none is ever left out.
class SpatialLightChoice {
 public:
  // What light `light`'s sample (u_within, u1, u2) brings to `point`, over
  // its density: any non-negative measure of brightness, the same for all.
  using Contribution = std::function<double(uint32_t light, PointWorld point, Real u_within, Real u1, Real u2)>;

  SpatialLightChoice(const kernel::Bounds3& scene_bounds, uint32_t lights, Contribution contribution);
  ~SpatialLightChoice();
  SpatialLightChoice(const SpatialLightChoice&) = delete;
  SpatialLightChoice& operator=(const SpatialLightChoice&) = delete;

  // Safe from any number of threads; a voxel's distribution is computed once
  // (a thread that loses the race to publish it drops its own copy).
  std::span<const Real> cdf_at(PointWorld point) const;

  static constexpr int kVoxelsAlongLongestSide = 64;
  static constexpr int kSamplesPerVoxel = 128;
  // With many lights, fewer points per voxel (128 · 64 / lights, at least 8):
  // a voxel then costs at most ~8 k light samples instead of 128 per light
  // (2000 lights: 8 s instead of 0.5 s for a 64² image at 1 spp before this).
  static int samples_per_voxel(uint32_t lights) {
    return static_cast<int>(std::clamp<uint64_t>(uint64_t{kSamplesPerVoxel} * 64 / std::max<uint32_t>(lights, 1), 8,
                                                 kSamplesPerVoxel));
  }
  // Voxels × lights at most (≈ 128 MiB of tables if every voxel were used):
  // scenes of thousands of lights get coarser voxels.
  static constexpr double kMaxTableEntries = 1 << 25;
  // The most bytes the tables of `lights` lights take, every voxel used (for
  // the render's memory estimate).
  static uint64_t most_bytes(uint64_t lights);

 private:
  Real* distribution_of(int x, int y, int z) const;

  kernel::Bounds3 bounds_;
  int voxels_[3] = {1, 1, 1};
  uint32_t lights_;
  Contribution contribution_;
  mutable std::unique_ptr<std::atomic<Real*>[]> cdfs_;  // one per voxel, null until asked for
};

}  // namespace safegi::render
