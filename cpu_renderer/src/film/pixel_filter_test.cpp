#include "film/pixel_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace safegi::render {
namespace {

// ∫ f(x) g(x) dx / ∫ f(x) dx over [-r, r] by the midpoint rule.
double filtered_mean(const PixelFilter& filter, double radius, const std::function<double(double)>& g) {
  const int n = 200000;
  double num = 0, den = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -radius + (i + 0.5) * 2 * radius / n;
    const double f = pixel_filter_value(filter, x, radius);
    num += f * g(x);
    den += f;
  }
  return num / den;
}

// The sampler's Σ w g(dx) / Σ w over a fine grid of (u, v): what a pixel's
// samples converge to, which must be the filter's own weighting of g.
double sampled_mean(const PixelFilterSampler& sampler, const std::function<double(double)>& g, bool along_y) {
  const int n = 8192;
  double num = 0, den = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 8; ++j) {
      const Real u = static_cast<Real>((i + 0.5) / n), v = static_cast<Real>((j + 0.5) / 8);
      PixelFilterSampler::Sample s = along_y ? sampler.sample(v, u) : sampler.sample(u, v);
      num += s.weight * g(along_y ? s.dy : s.dx);
      den += s.weight;
    }
  return num / den;
}

TEST(PixelFilter, SamplesWeighLikeTheFilter) {
  for (PixelFilterType type : {PixelFilterType::box, PixelFilterType::triangle, PixelFilterType::gaussian,
                               PixelFilterType::mitchell, PixelFilterType::sinc}) {
    PixelFilter filter;
    filter.type = type;
    filter.radius_x = type == PixelFilterType::sinc ? 4 : 2;
    filter.radius_y = 1.5;
    PixelFilterSampler sampler(filter);
    const std::function<double(double)> tests[] = {[](double x) { return x * x; },
                                                   [](double x) { return x > 0.3 ? 1.0 : 0.0; },
                                                   [](double x) { return std::cos(3 * x); }};
    for (const auto& g : tests) {
      EXPECT_NEAR(sampled_mean(sampler, g, false), filtered_mean(filter, filter.radius_x, g), 2e-3)
          << kPixelFilterNames[static_cast<int>(type)];
      EXPECT_NEAR(sampled_mean(sampler, g, true), filtered_mean(filter, filter.radius_y, g), 2e-3)
          << kPixelFilterNames[static_cast<int>(type)] << " along y";
    }
  }
}

TEST(PixelFilter, NegativeLobesGiveNegativeWeights) {
  PixelFilter mitchell;
  mitchell.type = PixelFilterType::mitchell;
  mitchell.radius_x = mitchell.radius_y = 2;
  EXPECT_LT(pixel_filter_value(mitchell, 1.5, 2), 0);
  PixelFilterSampler sampler(mitchell);
  bool negative = false;
  for (int i = 0; i < 64; ++i) negative = negative || sampler.sample(static_cast<Real>((i + 0.5) / 64), 0.5f).weight < 0;
  EXPECT_TRUE(negative);
  // pbrt-v3's Gaussian: exp(−α x²) less its value at the radius.
  PixelFilter gaussian;
  gaussian.type = PixelFilterType::gaussian;
  EXPECT_DOUBLE_EQ(pixel_filter_value(gaussian, 0.5, 2), std::exp(-0.5) - std::exp(-8.0));
  EXPECT_EQ(pixel_filter_value(gaussian, 2.5, 2), 0);
  EXPECT_TRUE(PixelFilterSampler::is_plain_box(PixelFilter{}));
}

}  // namespace
}  // namespace safegi::render
