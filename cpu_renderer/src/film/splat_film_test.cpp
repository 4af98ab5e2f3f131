// SplatFilm: where a sample's splat lands and with what weight, which pixels
// are sampled, and that tiles added out of order make the same sums.
#include "film/splat_film.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "film/pixel_filter.hpp"

namespace safegi::render {
namespace {

PixelFilter gaussian_filter() {
  PixelFilter filter;
  filter.type = PixelFilterType::gaussian;
  filter.mode = PixelFilterMode::splat;
  filter.radius_x = filter.radius_y = 2;
  return filter;
}

// pbrt-v3's Film::GetSampleBounds: the window grown by radius − 0.5, rounded out.
TEST(SplatFilm, SamplesThePixelsWithinReachOfTheWindow) {
  PixelFilter filter = gaussian_filter();
  EXPECT_EQ(SplatFilm(filter, {0, 0, 10, 6}).sample_bounds().x0, -2);
  EXPECT_EQ(SplatFilm(filter, {0, 0, 10, 6}).sample_bounds().x1, 12);
  filter.radius_x = 1.2;
  const PixelRect bounds = SplatFilm(filter, {3, 4, 10, 6}).sample_bounds();
  EXPECT_EQ(bounds.x0, 2);   // floor(3 + 0.5 − 1.2)
  EXPECT_EQ(bounds.x1, 11);  // ceil(10 − 0.5 + 1.2)
  EXPECT_EQ(bounds.y0, 2);
  EXPECT_EQ(bounds.y1, 8);
}

// One sample: each pixel whose centre is within the radius gets f(dx)·f(dy)
// times the radiance and f(dx)·f(dy) of weight; the others nothing.
TEST(SplatFilm, ASampleAddsToThePixelsWithinTheRadius) {
  const PixelFilter filter = gaussian_filter();
  SplatFilm film(filter, {0, 0, 8, 8});
  SplatFilm::TileSplats splats = film.tile_splats({2, 2, 4, 4});
  const double x = 3.3, y = 2.9;
  splats.add(x, y, {2.0, 4.0, 6.0});
  film.begin_pass(1, 1);
  film.add_in_order(0, std::move(splats));
  for (int qy = 0; qy < 8; ++qy)
    for (int qx = 0; qx < 8; ++qx) {
      const double dx = qx + 0.5 - x, dy = qy + 0.5 - y;
      const double weight = std::abs(dx) <= 2 && std::abs(dy) <= 2 ? pixel_filter_value(filter, dx, 2) *
                                                                         pixel_filter_value(filter, dy, 2)
                                                                   : 0;
      const double* sum = &film.sums()[4 * (qy * 8 + qx)];
      EXPECT_DOUBLE_EQ(sum[3], weight) << qx << "," << qy;
      EXPECT_DOUBLE_EQ(sum[0], 2 * weight);
      EXPECT_DOUBLE_EQ(sum[2], 6 * weight);
    }
  const std::vector<float> rgb = film.pixels();
  EXPECT_FLOAT_EQ(rgb[3 * (3 * 8 + 3) + 1], 4.0f);  // Σ f·L / Σ f
  EXPECT_EQ(rgb[3 * (7 * 8 + 7)], 0.0f);             // no weight: black
}

// Tiles finished in any order are added in tile order: the same bits.
TEST(SplatFilm, TilesAddedOutOfOrderGiveTheSameSums) {
  const PixelFilter filter = gaussian_filter();
  auto film_after = [&](std::vector<size_t> order) {
    SplatFilm film(filter, {0, 0, 8, 8});
    film.begin_pass(4, 1);
    const PixelRect tiles[] = {{0, 0, 4, 4}, {4, 0, 8, 4}, {0, 4, 4, 8}, {4, 4, 8, 8}};
    for (size_t t : order) {
      SplatFilm::TileSplats splats = film.tile_splats(tiles[t]);
      for (int i = 0; i < 16; ++i)
        splats.add(tiles[t].x0 + 0.37 * i * 0.7, tiles[t].y0 + 0.11 * i, {0.1 * i + t, 1.0 / (i + 1), 3.0});
      film.add_in_order(t, std::move(splats));
    }
    return film.sums();
  };
  const std::vector<double> in_order = film_after({0, 1, 2, 3});
  EXPECT_EQ(film_after({3, 1, 2, 0}), in_order);
  EXPECT_EQ(film_after({2, 0, 3, 1}), in_order);
}

}  // namespace
}  // namespace safegi::render
