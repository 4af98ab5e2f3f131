// pbrt-v3's pixel filters (box, triangle, gaussian, mitchell, sinc; all
// separable), applied by importance sampling as pbrt-v4's FilterSampler does:
// each camera sample lands at its pixel's centre plus an offset drawn in
// proportion to |f| and carries the weight f / pdf, and a pixel is Σ w·L / Σ w.
// That converges to pbrt-v3's filtered image (Σ f·L / Σ f over the samples
// within the filter's radius) while every sample stays in its own pixel:
// tiles, crops and ranks need no borders.
#pragma once

#include <algorithm>
#include <vector>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// The filter's value at offset `x` (pixels) along an axis of radius `radius`.
double pixel_filter_value(const PixelFilter& filter, double x, double radius);

// A filtered pixel's channel, Σ w·L / Σ w; black, as pbrt-v3's Film writes it,
// where a negative lobe makes it negative or the weights cancel.
inline float filtered_pixel(double weighted_sum, double weight_sum) {
  return weight_sum != 0 ? static_cast<float>(std::max(0.0, weighted_sum / weight_sum)) : 0.0f;
}

class PixelFilterSampler {
 public:
  explicit PixelFilterSampler(const PixelFilter& filter);

  // A box one pixel wide: uniform over the pixel, every weight 1 (the camera's own sampling).
  static bool is_plain_box(const PixelFilter& filter);

  struct Sample {
    Real dx = 0, dy = 0;  // from the pixel's centre, pixels (y down the image)
    Real weight = 1;      // f / pdf: negative in a negative lobe
  };
  Sample sample(Real u, Real v) const;

 private:
  // |f| along one axis, tabulated over [-radius, radius] (each bin the largest
  // of its ends and centre, so no part where f is not 0 has density 0).
  struct Axis {
    double radius = 0.5;
    std::vector<double> cdf;  // kBins + 1 running sums, normalised
    std::vector<double> density;  // per bin, per pixel
  };
  Axis tabulate(double radius) const;
  // An offset along `axis` and its f / pdf.
  void sample_axis(const Axis& axis, Real u, Real& offset, double& weight) const;

  static constexpr int kBins = 64;
  PixelFilter filter_;
  Axis x_, y_;
};

}  // namespace safegi::render
