#include "film/splat_film.hpp"

#include <algorithm>
#include <cmath>

#include "film/pixel_filter.hpp"

namespace safegi::render {

SplatFilm::SplatFilm(const PixelFilter& filter, const PixelRect& window)
    : filter_(filter),
      window_(window),
      // A sample at x reaches the pixels q with |q + 0.5 − x| ≤ radius: from
      // its own pixel, floor(radius + 0.5) either way.
      reach_x_(static_cast<int>(std::floor(filter.radius_x + 0.5))),
      reach_y_(static_cast<int>(std::floor(filter.radius_y + 0.5))),
      sums_(4 * static_cast<size_t>(window.x1 - window.x0) * (window.y1 - window.y0), 0.0) {
  sample_bounds_ = {static_cast<int>(std::floor(window.x0 + 0.5 - filter.radius_x)),
                    static_cast<int>(std::floor(window.y0 + 0.5 - filter.radius_y)),
                    static_cast<int>(std::ceil(window.x1 - 0.5 + filter.radius_x)),
                    static_cast<int>(std::ceil(window.y1 - 0.5 + filter.radius_y))};
}

SplatFilm::TileSplats SplatFilm::tile_splats(const PixelRect& sampled) const {
  TileSplats splats;
  splats.film_ = this;
  PixelRect& reach = splats.reach_;
  reach.x0 = std::clamp(sampled.x0 - reach_x_, window_.x0, window_.x1);
  reach.y0 = std::clamp(sampled.y0 - reach_y_, window_.y0, window_.y1);
  reach.x1 = std::clamp(sampled.x1 + reach_x_, reach.x0, window_.x1);
  reach.y1 = std::clamp(sampled.y1 + reach_y_, reach.y0, window_.y1);
  splats.sums_.assign(4 * static_cast<size_t>(reach.x1 - reach.x0) * (reach.y1 - reach.y0), 0.0);
  return splats;
}

void SplatFilm::TileSplats::add(double x, double y, const double (&L)[3]) {
  const PixelFilter& filter = film_->filter_;
  // The pixels whose centres q + 0.5 lie within the radius of (x, y), clipped to this buffer.
  const int x0 = std::max(reach_.x0, static_cast<int>(std::ceil(x - 0.5 - filter.radius_x)));
  const int x1 = std::min(reach_.x1 - 1, static_cast<int>(std::floor(x - 0.5 + filter.radius_x)));
  const int y0 = std::max(reach_.y0, static_cast<int>(std::ceil(y - 0.5 - filter.radius_y)));
  const int y1 = std::min(reach_.y1 - 1, static_cast<int>(std::floor(y - 0.5 + filter.radius_y)));
  if (x0 > x1 || y0 > y1) return;
  weights_x_.resize(x1 - x0 + 1);
  weights_y_.resize(y1 - y0 + 1);
  for (int q = x0; q <= x1; ++q) weights_x_[q - x0] = pixel_filter_value(filter, q + 0.5 - x, filter.radius_x);
  for (int q = y0; q <= y1; ++q) weights_y_[q - y0] = pixel_filter_value(filter, q + 0.5 - y, filter.radius_y);
  const size_t row_length = reach_.x1 - reach_.x0;
  for (int qy = y0; qy <= y1; ++qy) {
    double* pixel = &sums_[4 * ((qy - reach_.y0) * row_length + (x0 - reach_.x0))];
    for (int qx = x0; qx <= x1; ++qx, pixel += 4) {
      const double weight = weights_x_[qx - x0] * weights_y_[qy - y0];
      pixel[0] += weight * L[0];
      pixel[1] += weight * L[1];
      pixel[2] += weight * L[2];
      pixel[3] += weight;
    }
  }
}

uint64_t SplatFilm::tile_splats_bytes(const PixelFilter& filter, int tile_side) {
  const uint64_t width = tile_side + 2 * static_cast<uint64_t>(std::floor(filter.radius_x + 0.5));
  const uint64_t height = tile_side + 2 * static_cast<uint64_t>(std::floor(filter.radius_y + 0.5));
  return width * height * 4 * sizeof(double);
}

void SplatFilm::begin_pass(size_t tile_count, int threads) { order_.begin_pass(tile_count, threads, kTilesAheadPerThread); }

void SplatFilm::wait_for_room(size_t index) { order_.wait_for_room(index); }

void SplatFilm::add_in_order(size_t index, TileSplats&& splats) {
  order_.add_in_order(index, std::move(splats), [&](const TileSplats& ready) { add_now(ready); });
}

void SplatFilm::add_now(const TileSplats& splats) {
  const PixelRect& reach = splats.reach_;
  const size_t window_width = window_.x1 - window_.x0, row_length = reach.x1 - reach.x0;
  for (int y = reach.y0; y < reach.y1; ++y) {
    const double* from = &splats.sums_[4 * (y - reach.y0) * row_length];
    double* to = &sums_[4 * ((y - window_.y0) * window_width + (reach.x0 - window_.x0))];
    for (size_t i = 0; i < 4 * row_length; ++i) to[i] += from[i];
  }
}

std::vector<float> SplatFilm::pixels() const {
  std::vector<float> rgb(3 * (sums_.size() / 4));
  for (size_t pixel = 0; pixel < sums_.size() / 4; ++pixel) {
    const double* sum = &sums_[4 * pixel];
    for (int c = 0; c < 3; ++c) rgb[3 * pixel + c] = filtered_pixel(sum[c], sum[3]);
  }
  return rgb;
}

}  // namespace safegi::render
