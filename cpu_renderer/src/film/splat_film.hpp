// pbrt-v3's film reconstruction (Film::AddSample): every sample, taken
// uniformly in its pixel, adds f(d)·L and f(d) to each pixel whose centre lies
// within the filter's radius of it (d the offset from that centre), and a
// pixel is Σ f·L / Σ f. Pixels just outside the window are sampled too, so that
// the window's edge pixels get their neighbours' samples as inner ones do.
//
// A tile splats into a buffer of its own (its pixels and the filter's reach
// around them); buffers are added to the film in tile order, whichever thread
// finished them, so the image does not depend on the thread count. A thread
// waits before starting a tile too far ahead of the next one to add, so the
// buffers waiting stay few (kTilesAheadPerThread per thread).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "film/tile_order.hpp"

namespace safegi::render {

class SplatFilm {
 public:
  // `window`: the pixels the film holds, in image coordinates.
  SplatFilm(const PixelFilter& filter, const PixelRect& window);

  // The pixels whose samples reach the window (pbrt-v3's GetSampleBounds).
  PixelRect sample_bounds() const { return sample_bounds_; }

  class TileSplats {
   public:
    // Adds radiance `L` (r, g, b) of a sample at film position (x, y), in pixels from the image's corner.
    void add(double x, double y, const double (&L)[3]);

   private:
    friend class SplatFilm;
    const SplatFilm* film_ = nullptr;
    PixelRect reach_{0, 0, 0, 0};  // the window's pixels that `sampled` can reach
    std::vector<double> sums_;     // r, g, b, weight per pixel of reach_
    std::vector<double> weights_x_, weights_y_;  // scratch: one sample's filter values per column and row
  };
  // An empty buffer for the splats of the samples of pixels `sampled`.
  TileSplats tile_splats(const PixelRect& sampled) const;

  static constexpr int kTilesAheadPerThread = 8;
  // The most a tile's buffer holds, for tiles of `tile_side` pixels.
  static uint64_t tile_splats_bytes(const PixelFilter& filter, int tile_side);

  // Before each pass over the tiles: `tile_count` buffers will be added, with
  // indices 0 .. tile_count-1, by `threads` threads.
  void begin_pass(size_t tile_count, int threads);
  // Returns when tile `index` may start: few enough tiles before it wait to be added.
  void wait_for_room(size_t index);
  // Adds tile `index`'s splats once every lower index's are in. Thread-safe.
  void add_in_order(size_t index, TileSplats&& splats);

  // The window's pixels: r, g, b, weight each, row by row (for summing over processes).
  std::vector<double>& sums() { return sums_; }
  // Σ f·L / Σ f per pixel (filtered_pixel).
  std::vector<float> pixels() const;

 private:
  void add_now(const TileSplats& splats);

  PixelFilter filter_;
  PixelRect window_, sample_bounds_;
  int reach_x_, reach_y_;  // how many pixels a sample's splat extends each side of its own
  std::vector<double> sums_;
  TileOrder<TileSplats> order_;
};

}  // namespace safegi::render
