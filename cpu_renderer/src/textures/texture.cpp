#include "safegi/cpu_renderer/texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace safegi::render {

float srgb_to_linear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

Image to_linear_texels(Image image, ColourSpace space, float scale, bool flip_rows) {
  for (float& v : image.rgb) v = (space == ColourSpace::srgb ? srgb_to_linear(std::clamp(v, 0.0f, 1.0f)) : v) * scale;
  if (flip_rows) {
    const size_t row = 3 * static_cast<size_t>(image.width);
    for (int y = 0; y < image.height / 2; ++y)
      std::swap_ranges(image.rgb.begin() + y * row, image.rgb.begin() + (y + 1) * row,
                       image.rgb.begin() + (image.height - 1 - y) * row);
  }
  return image;
}

MipMap::MipMap(Image image, TextureWrap wrap) : wrap_(wrap) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != 3 * static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
    throw std::invalid_argument("a texture needs width × height RGB texels");
  levels_.push_back({image.width, image.height, std::move(image.rgb)});
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& fine = levels_.back();
    Level coarse{(fine.width + 1) / 2, (fine.height + 1) / 2, {}};
    coarse.rgb.resize(3 * static_cast<size_t>(coarse.width) * coarse.height);
    for (int y = 0; y < coarse.height; ++y)
      for (int x = 0; x < coarse.width; ++x)
        for (int c = 0; c < 3; ++c) {
          float sum = 0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              int fx = std::min(2 * x + dx, fine.width - 1), fy = std::min(2 * y + dy, fine.height - 1);
              sum += fine.rgb[3 * (static_cast<size_t>(fy) * fine.width + fx) + c];
            }
          coarse.rgb[3 * (static_cast<size_t>(y) * coarse.width + x) + c] = 0.25f * sum;
        }
    levels_.push_back(std::move(coarse));
  }
}

Texel MipMap::texel(int level, int x, int y) const {
  const Level& l = levels_[level];
  switch (wrap_) {
    case TextureWrap::repeat:
      x = ((x % l.width) + l.width) % l.width;
      y = ((y % l.height) + l.height) % l.height;
      break;
    case TextureWrap::clamp:
      x = std::clamp(x, 0, l.width - 1);
      y = std::clamp(y, 0, l.height - 1);
      break;
    case TextureWrap::black:
      if (x < 0 || y < 0 || x >= l.width || y >= l.height) return Texel{};
      break;
    case TextureWrap::longitude_latitude:
      x = ((x % l.width) + l.width) % l.width;
      y = std::clamp(y, 0, l.height - 1);
      break;
  }
  const float* v = &l.rgb[3 * (static_cast<size_t>(y) * l.width + x)];
  return Texel(v[0], v[1], v[2]);
}

Texel MipMap::bilinear(int level, Real s, Real t) const {
  level = std::clamp(level, 0, levels() - 1);
  const Level& l = levels_[level];
  // Texel centres sit at half-integers: (s·w − ½) is measured between them.
  Real x = s * static_cast<Real>(l.width) - Real(0.5), y = t * static_cast<Real>(l.height) - Real(0.5);
  Real x0 = std::floor(x), y0 = std::floor(y);
  Real dx = x - x0, dy = y - y0;
  int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  return (1 - dx) * (1 - dy) * texel(level, ix, iy) + dx * (1 - dy) * texel(level, ix + 1, iy) +
         (1 - dx) * dy * texel(level, ix, iy + 1) + dx * dy * texel(level, ix + 1, iy + 1);
}

Texel MipMap::trilinear(Real s, Real t, Real width) const {
  const Real texels = width * static_cast<Real>(std::max(levels_[0].width, levels_[0].height));
  const Real level = std::log2(std::max(texels, Real(1e-8)));
  if (!(level > 0)) return bilinear(0, s, t);
  if (level >= static_cast<Real>(levels() - 1)) return texel(levels() - 1, 0, 0);
  const int fine = static_cast<int>(std::floor(level));
  const Real blend = level - static_cast<Real>(fine);
  return (1 - blend) * bilinear(fine, s, t) + blend * bilinear(fine + 1, s, t);
}

namespace {

// pbrt-v3's table of the EWA filter's Gaussian, e^(−2r²) − e^(−2), by r² in [0, 1).
constexpr int kEwaWeightCount = 128;
const std::array<Real, kEwaWeightCount> kEwaWeights = [] {
  std::array<Real, kEwaWeightCount> weights{};
  for (int i = 0; i < kEwaWeightCount; ++i) {
    const Real r2 = static_cast<Real>(i) / static_cast<Real>(kEwaWeightCount - 1);
    weights[i] = std::exp(-2 * r2) - std::exp(Real(-2));
  }
  return weights;
}();

}  // namespace

Texel MipMap::ewa(Real s, Real t, StExtent a, StExtent b, Real max_anisotropy) const {
  auto length = [](StExtent e) { return std::sqrt(e.s * e.s + e.t * e.t); };
  if (length(a) < length(b)) std::swap(a, b);
  const Real major = length(a);
  Real minor = length(b);
  if (minor * max_anisotropy < major && minor > 0) {
    const Real stretch = major / (minor * max_anisotropy);
    b = {b.s * stretch, b.t * stretch};
    minor *= stretch;
  }
  if (!(minor > 0) || !std::isfinite(major)) return bilinear(0, s, t);
  const Real texels = minor * static_cast<Real>(std::max(levels_[0].width, levels_[0].height));
  const Real level = std::max(Real(0), std::log2(texels));
  if (level >= static_cast<Real>(levels() - 1)) return texel(levels() - 1, 0, 0);
  const int fine = static_cast<int>(std::floor(level));
  const Real blend = level - static_cast<Real>(fine);
  return (1 - blend) * ewa_on_level(fine, s, t, a, b) + blend * ewa_on_level(fine + 1, s, t, a, b);
}

Texel MipMap::ewa_on_level(int level, Real s, Real t, StExtent a, StExtent b) const {
  // At most this many texels from the centre to the filter's edge: a needle
  // longer than that at its level (a large max_anisotropy) is filtered on the
  // next coarser level instead, blurred across, so no lookup reads more than
  // about 128² texels.
  constexpr Real kMaxTexelsAcross = 64;
  for (;; ++level) {
    if (level >= levels() - 1) return texel(levels() - 1, 0, 0);
    const Level& l = levels_[level];
    const Real w = static_cast<Real>(l.width), h = static_cast<Real>(l.height);
    // In this level's texels, centres at integers.
    const Real x = s * w - Real(0.5), y = t * h - Real(0.5);
    const StExtent pa{a.s * w, a.t * h}, pb{b.s * w, b.t * h};
    // The ellipse A x² + B x y + C y² < 1, widened by a texel so that it covers one at least.
    Real qa = pa.t * pa.t + pb.t * pb.t + 1, qb = -2 * (pa.s * pa.t + pb.s * pb.t), qc = pa.s * pa.s + pb.s * pb.s + 1;
    const Real inverse_f = 1 / (qa * qc - qb * qb * Real(0.25));
    qa *= inverse_f;
    qb *= inverse_f;
    qc *= inverse_f;
    const Real determinant = -qb * qb + 4 * qa * qc;
    const Real half_width = 2 * std::sqrt(determinant * qc) / determinant;
    const Real half_height = 2 * std::sqrt(determinant * qa) / determinant;
    if (!(half_width < kMaxTexelsAcross && half_height < kMaxTexelsAcross)) continue;
    const int x0 = static_cast<int>(std::ceil(x - half_width)), x1 = static_cast<int>(std::floor(x + half_width));
    const int y0 = static_cast<int>(std::ceil(y - half_height)), y1 = static_cast<int>(std::floor(y + half_height));
    Texel sum{};
    Real weights = 0;
    for (int iy = y0; iy <= y1; ++iy) {
      const Real dy = static_cast<Real>(iy) - y;
      for (int ix = x0; ix <= x1; ++ix) {
        const Real dx = static_cast<Real>(ix) - x;
        const Real r2 = qa * dx * dx + qb * dx * dy + qc * dy * dy;
        if (r2 >= 1) continue;
        const Real weight = kEwaWeights[std::min(static_cast<int>(r2 * kEwaWeightCount), kEwaWeightCount - 1)];
        sum += weight * texel(level, ix, iy);
        weights += weight;
      }
    }
    return weights > 0 ? sum / weights : bilinear(level, s, t);
  }
}

Texel MipMap::average() const {
  const Level& l = levels_[0];
  double sum[3] = {0, 0, 0};
  for (size_t i = 0; i < l.rgb.size(); i += 3)
    for (int c = 0; c < 3; ++c) sum[c] += l.rgb[i + c];
  const double n = static_cast<double>(l.width) * l.height;
  return Texel(static_cast<Real>(sum[0] / n), static_cast<Real>(sum[1] / n), static_cast<Real>(sum[2] / n));
}

Texel MipMap::maximum() const {
  float most[3] = {0, 0, 0};
  const std::vector<float>& rgb = levels_[0].rgb;
  for (size_t i = 0; i < rgb.size(); i += 3)
    for (int c = 0; c < 3; ++c) most[c] = std::max(most[c], rgb[i + c]);
  return Texel(most[0], most[1], most[2]);
}

}  // namespace safegi::render
