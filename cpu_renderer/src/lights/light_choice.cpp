#include "lights/light_choice.hpp"

#include <algorithm>
#include <cmath>

namespace safegi::render {

namespace {

// The radical inverse of i in `base` (Halton's points, as pbrt-v3's voxels use).
Real radical_inverse(uint32_t i, uint32_t base) {
  double inverse = 1.0 / base, value = 0, scale = inverse;
  for (; i > 0; i /= base, scale *= inverse) value += static_cast<double>(i % base) * scale;
  return static_cast<Real>(std::min(value, 1.0 - 1e-7));
}

}  // namespace

std::vector<Real> light_cdf(std::span<const double> weights) {
  double total = 0;
  for (double w : weights) total += w;
  const bool uniform = !(total > 0) || !std::isfinite(total);
  std::vector<Real> cdf;
  cdf.reserve(weights.size());
  double running = 0;
  for (double w : weights) {
    running += uniform ? 1.0 / static_cast<double>(weights.size()) : w / total;
    cdf.push_back(static_cast<Real>(running));
  }
  if (!cdf.empty()) cdf.back() = 1;
  return cdf;
}

ChosenLight choose_light(std::span<const Real> cdf, Real u) {
  auto found = std::upper_bound(cdf.begin(), cdf.end(), u);
  ChosenLight chosen;
  chosen.index = static_cast<uint32_t>(std::min<ptrdiff_t>(found - cdf.begin(), static_cast<ptrdiff_t>(cdf.size()) - 1));
  chosen.probability = light_probability(cdf, chosen.index);
  const Real low = chosen.index == 0 ? Real(0) : cdf[chosen.index - 1];
  chosen.u_within = chosen.probability > 0 ? std::clamp((u - low) / chosen.probability, Real(0), Real(0x1.fffffep-1f))
                                           : Real(0);
  return chosen;
}

Real light_probability(std::span<const Real> cdf, uint32_t light) {
  return cdf[light] - (light == 0 ? Real(0) : cdf[light - 1]);
}

SpatialLightChoice::SpatialLightChoice(const kernel::Bounds3& scene_bounds, uint32_t lights, Contribution contribution)
    : bounds_(scene_bounds), lights_(lights), contribution_(std::move(contribution)) {
  if (bounds_.empty()) bounds_.extend(kernel::Real3{0, 0, 0});
  const kernel::Real3 extent = bounds_.extent();
  const Real longest = std::max({extent.x, extent.y, extent.z});
  // Fewer voxels where many lights would make the tables outgrow kMaxTableEntries.
  for (int along_longest = kVoxelsAlongLongestSide;; along_longest /= 2) {
    for (int axis = 0; axis < 3; ++axis)
      voxels_[axis] = longest > 0 ? std::max(1, static_cast<int>(std::lround(extent[axis] / longest * along_longest))) : 1;
    const double entries = static_cast<double>(voxels_[0]) * voxels_[1] * voxels_[2] * std::max<uint32_t>(lights_, 1);
    if (entries <= kMaxTableEntries || along_longest == 1) break;
  }
  const size_t count = static_cast<size_t>(voxels_[0]) * voxels_[1] * voxels_[2];
  cdfs_ = std::make_unique<std::atomic<Real*>[]>(count);
  for (size_t i = 0; i < count; ++i) cdfs_[i].store(nullptr, std::memory_order_relaxed);
}

uint64_t SpatialLightChoice::most_bytes(uint64_t lights) {
  // The finest grid's slots, and a distribution in each voxel up to
  // kMaxTableEntries entries (the constructor coarsens the grid past them).
  const uint64_t voxels = uint64_t{kVoxelsAlongLongestSide} * kVoxelsAlongLongestSide * kVoxelsAlongLongestSide;
  const uint64_t entries = std::min(voxels * lights, std::max(static_cast<uint64_t>(kMaxTableEntries), lights));
  return voxels * sizeof(std::atomic<Real*>) + entries * sizeof(Real);
}

SpatialLightChoice::~SpatialLightChoice() {
  const size_t count = static_cast<size_t>(voxels_[0]) * voxels_[1] * voxels_[2];
  for (size_t i = 0; i < count; ++i) delete[] cdfs_[i].load(std::memory_order_relaxed);
}

std::span<const Real> SpatialLightChoice::cdf_at(PointWorld point) const {
  const kernel::Real3 p = to_kernel(point), extent = bounds_.extent();
  int cell[3];
  for (int axis = 0; axis < 3; ++axis) {
    const Real offset = extent[axis] > 0 ? (p[axis] - bounds_.lower[axis]) / extent[axis] : Real(0);
    // NaN and points outside the box go to the nearest voxel.
    const Real scaled = offset * static_cast<Real>(voxels_[axis]);
    cell[axis] = scaled > 0 ? std::min(static_cast<int>(std::min(scaled, Real(1 << 20))), voxels_[axis] - 1) : 0;
  }
  return {distribution_of(cell[0], cell[1], cell[2]), lights_};
}

Real* SpatialLightChoice::distribution_of(int x, int y, int z) const {
  std::atomic<Real*>& slot = cdfs_[(static_cast<size_t>(z) * voxels_[1] + y) * voxels_[0] + x];
  if (Real* ready = slot.load(std::memory_order_acquire)) return ready;

  const kernel::Real3 size = bounds_.extent();
  const kernel::Real3 lower{bounds_.lower.x + size.x * static_cast<Real>(x) / static_cast<Real>(voxels_[0]),
                            bounds_.lower.y + size.y * static_cast<Real>(y) / static_cast<Real>(voxels_[1]),
                            bounds_.lower.z + size.z * static_cast<Real>(z) / static_cast<Real>(voxels_[2])};
  const kernel::Real3 cell{size.x / static_cast<Real>(voxels_[0]), size.y / static_cast<Real>(voxels_[1]),
                           size.z / static_cast<Real>(voxels_[2])};
  std::vector<double> contributions(lights_, 0.0);
  const int points = samples_per_voxel(lights_);
  for (int i = 0; i < points; ++i) {
    const uint32_t n = static_cast<uint32_t>(i);
    const kernel::Real3 offset{radical_inverse(n, 2), radical_inverse(n, 3), radical_inverse(n, 5)};
    const PointWorld point = from_kernel<PointWorld>(lower + cell * offset);
    const Real u1 = radical_inverse(n, 7), u2 = radical_inverse(n, 11), u_within = radical_inverse(n, 13);
    for (uint32_t light = 0; light < lights_; ++light) {
      const double c = contribution_(light, point, u_within, u1, u2);
      if (c > 0 && std::isfinite(c)) contributions[light] += c;
    }
  }
  double sum = 0;
  for (double c : contributions) sum += c;
  const double mean = sum / (static_cast<double>(points) * lights_);
  const double floor = mean > 0 ? 1e-3 * mean : 1.0;
  for (double& c : contributions) c = std::max(c, floor);
  std::vector<Real> cdf = light_cdf(contributions);

  Real* made = new Real[lights_];
  std::copy(cdf.begin(), cdf.end(), made);
  Real* expected = nullptr;
  if (slot.compare_exchange_strong(expected, made, std::memory_order_acq_rel, std::memory_order_acquire)) return made;
  delete[] made;
  return expected;
}

}  // namespace safegi::render
