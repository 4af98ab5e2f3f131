#include "film/pixel_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace safegi::render {

namespace {

double sinc(double x) {
  x = std::abs(x);
  if (x < 1e-5) return 1;
  const double pi_x = std::numbers::pi * x;
  return std::sin(pi_x) / pi_x;
}

// pbrt-v3's MitchellFilter::Mitchell1D, of x in [-1, 1] (the offset over the radius).
double mitchell(double x, double b, double c) {
  x = std::abs(2 * x);
  if (x > 1)
    return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) / 6;
  return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
}

}  // namespace

double pixel_filter_value(const PixelFilter& filter, double x, double radius) {
  if (std::abs(x) > radius) return 0;
  switch (filter.type) {
    case PixelFilterType::box:
      return 1;
    case PixelFilterType::triangle:
      return std::max(0.0, radius - std::abs(x));
    case PixelFilterType::gaussian:
      return std::max(0.0, std::exp(-filter.gaussian_alpha * x * x) - std::exp(-filter.gaussian_alpha * radius * radius));
    case PixelFilterType::mitchell:
      return mitchell(x / radius, filter.mitchell_b, filter.mitchell_c);
    case PixelFilterType::sinc:
      return sinc(x) * sinc(x / filter.sinc_tau);
  }
  return 0;
}

bool PixelFilterSampler::is_plain_box(const PixelFilter& filter) {
  return filter.type == PixelFilterType::box && filter.radius_x == 0.5 && filter.radius_y == 0.5;
}

PixelFilterSampler::PixelFilterSampler(const PixelFilter& filter)
    : filter_(filter), x_(tabulate(filter.radius_x)), y_(tabulate(filter.radius_y)) {}

PixelFilterSampler::Axis PixelFilterSampler::tabulate(double radius) const {
  Axis axis;
  axis.radius = radius;
  const double width = 2 * radius / kBins;
  axis.density.resize(kBins);
  axis.cdf.assign(kBins + 1, 0.0);
  for (int i = 0; i < kBins; ++i) {
    const double left = -radius + i * width;
    double value = 0;
    for (double x : {left, left + 0.5 * width, left + width})
      value = std::max(value, std::abs(pixel_filter_value(filter_, x, radius)));
    axis.density[i] = value;
    axis.cdf[i + 1] = axis.cdf[i] + value * width;
  }
  const double total = axis.cdf[kBins];
  for (int i = 0; i < kBins; ++i) {
    // A filter that is 0 everywhere (a degenerate Gaussian): uniform, every weight 0 but for the centre's.
    axis.density[i] = total > 0 ? axis.density[i] / total : 1 / (2 * radius);
    axis.cdf[i + 1] = total > 0 ? axis.cdf[i + 1] / total : static_cast<double>(i + 1) / kBins;
  }
  axis.cdf[kBins] = 1;
  return axis;
}

void PixelFilterSampler::sample_axis(const Axis& axis, Real u, Real& offset, double& weight) const {
  const double uu = std::clamp(static_cast<double>(u), 0.0, 1.0);
  const auto found = std::upper_bound(axis.cdf.begin() + 1, axis.cdf.end(), uu);
  const int bin = std::min(static_cast<int>(found - axis.cdf.begin()) - 1, kBins - 1);
  const double share = axis.cdf[bin + 1] - axis.cdf[bin];
  const double t = share > 0 ? std::clamp((uu - axis.cdf[bin]) / share, 0.0, 1.0) : 0.5;
  const double width = 2 * axis.radius / kBins;
  const double x = -axis.radius + (bin + t) * width;
  offset = static_cast<Real>(x);
  weight = axis.density[bin] > 0 ? pixel_filter_value(filter_, x, axis.radius) / axis.density[bin] : 0;
}

PixelFilterSampler::Sample PixelFilterSampler::sample(Real u, Real v) const {
  Sample s;
  double wx = 1, wy = 1;
  sample_axis(x_, u, s.dx, wx);
  sample_axis(y_, v, s.dy, wy);
  s.weight = static_cast<Real>(wx * wy);
  return s;
}

}  // namespace safegi::render
