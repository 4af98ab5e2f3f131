#include "safegi/cpu_renderer/texture.hpp"

#include <algorithm>
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
