// RenderPartition, in one process: the parts of a render, each rendering every
// N-th tile, put together are the whole render bit for bit (what a distributed
// render relies on; the MPI tests are in distributed_test.cpp).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {
namespace {

// One part of `parts`, with no other process to agree with.
class LonePart final : public RenderPartition {
 public:
  LonePart(int part, int parts) : part_(part), parts_(parts) {}
  int part() const override { return part_; }
  int parts() const override { return parts_; }
  double slowest_pass_seconds(double seconds) override { return seconds; }
  int next_pass_spp_of_first(int next_pass_spp) override { return next_pass_spp; }
  void sum_to_first(std::vector<double>&) override {}

 private:
  int part_, parts_;
};

TEST(RenderPartition, TilesCoverTheWindowOnce) {
  std::vector<int> covered(37 * 21, 0);
  std::vector<PixelRect> tiles = render_tiles(37, 21);
  EXPECT_EQ(tiles.size(), 3u * 2u);
  for (const PixelRect& tile : tiles)
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x) ++covered[y * 37 + x];
  for (int n : covered) EXPECT_EQ(n, 1);
}

TEST(RenderPartition, PartsTogetherAreTheWholeImage) {
  Scene scene = load_scene(std::filesystem::path(SAFEGI_SCENES_DIR) / "motion-blur.json");
  RenderOptions options;
  options.settings = scene.settings;
  options.settings.width = 45;
  options.settings.height = 38;
  options.settings.spp = 3;
  options.crop = CropWindow{3, 2, 40, 35};
  options.threads = 2;
  Image whole = render(scene, options);
  for (int parts : {2, 3, 5}) {
    std::vector<Image> images;
    for (int part = 0; part < parts; ++part) {
      LonePart partition(part, parts);
      options.partition = &partition;
      RenderStats stats;
      images.push_back(render(scene, options, &stats));
      EXPECT_EQ(stats.samples_per_pixel, 3);
    }
    options.partition = nullptr;
    std::vector<PixelRect> tiles = render_tiles(whole.width, whole.height);
    for (size_t t = 0; t < tiles.size(); ++t) {
      const Image& mine = images[t % parts];
      const Image& other = images[(t + 1) % parts];
      for (int y = tiles[t].y0; y < tiles[t].y1; ++y) {
        size_t bytes = 3 * sizeof(float) * (tiles[t].x1 - tiles[t].x0);
        EXPECT_EQ(std::memcmp(mine.pixel(tiles[t].x0, y), whole.pixel(tiles[t].x0, y), bytes), 0)
            << parts << " parts, tile " << t << ", row " << y;
        // A part leaves the others' tiles black.
        for (int x = tiles[t].x0; x < tiles[t].x1; ++x) EXPECT_EQ(other.pixel(x, y)[0], 0.0f);
      }
    }
  }
}

}  // namespace
}  // namespace safegi::render
