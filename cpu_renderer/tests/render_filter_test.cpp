// Pixel filters (pixel_filter.hpp) in whole renders: an emitter's straight
// edge seen by an orthographic camera, each column of pixels against the share
// of the filter's weight that lies on the emitter's side.
#include <algorithm>

#include "film/pixel_filter.hpp"
#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// A unit emitter over x < 0, seen face on across 16 × 8 pixels of 0.25 m: its
// edge is the boundary between columns 7 and 8.
constexpr const char* kEdge = R"j({
  "render": {"resolution": [16, 8], "integrator": "path", "filter": FILTER},
  "camera": {"projection": "orthographic", "position": ["0 m", "0 m", "5 m"], "look_at": ["0 m", "0 m", "0 m"],
             "up": [0, 1, 0], "view_size": "2 m"},
  "shapes": [{"type": "quad", "origin": ["-10 m", "-10 m", "0 m"], "edge_u": ["10 m", "0 m", "0 m"],
              "edge_v": ["0 m", "20 m", "0 m"], "emission": "1 W/(m2 sr)"}]})j";

// The filter's weight beyond `edge` pixels to the left of a pixel's centre, over its whole weight.
double share_left_of(const PixelFilter& filter, double edge) {
  const int n = 100000;
  double left = 0, all = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -filter.radius_x + (i + 0.5) * 2 * filter.radius_x / n;
    const double f = pixel_filter_value(filter, x, filter.radius_x);
    all += f;
    if (x < edge) left += f;
  }
  return left / all;
}

Scene edge_scene(const std::string& filter_json) {
  std::string text = kEdge;
  text.replace(text.find("FILTER"), 6, filter_json);
  return parse_scene(text, "test.json", SAFEGI_SCENES_DIR);
}

// Both modes converge to the same filtered image: each is checked against it.
TEST(RenderFilter, AnEdgeIsBlurredByTheFilter) {
  const std::pair<const char*, PixelFilterType> filters[] = {
      {R"({"type": "box"})", PixelFilterType::box},
      {R"({"type": "box", "radius": [1.5, 1.5]})", PixelFilterType::box},
      {R"({"type": "triangle"})", PixelFilterType::triangle},
      {R"({"type": "gaussian"})", PixelFilterType::gaussian},
      {R"({"type": "mitchell"})", PixelFilterType::mitchell},
      {R"({"type": "sinc"})", PixelFilterType::sinc},
      {R"({"type": "box", "radius": [1.5, 1.5], "mode": "splat"})", PixelFilterType::box},
      {R"({"type": "triangle", "mode": "splat"})", PixelFilterType::triangle},
      {R"({"type": "gaussian", "mode": "splat"})", PixelFilterType::gaussian},
      {R"({"type": "mitchell", "mode": "splat"})", PixelFilterType::mitchell},
      {R"({"type": "sinc", "mode": "splat"})", PixelFilterType::sinc}};
  for (auto [json, type] : filters) {
    const Scene scene = edge_scene(json);
    const PixelFilter& filter = scene.settings.filter;
    ASSERT_EQ(filter.type, type);
    ASSERT_EQ(filter.mode, std::string_view(json).find("splat") != std::string_view::npos ? PixelFilterMode::splat
                                                                                            : PixelFilterMode::sample);
    const Image image = render_scene(scene, 256);
    for (int column = 0; column < 16; ++column) {
      double mean = 0;
      for (int row = 0; row < 8; ++row) mean += image.rgb[3 * (row * 16 + column)] / 8.0;
      const double expected = share_left_of(filter, 8 - (column + 0.5));
      // Negative lobes: a pixel below 0 is written as 0, as pbrt-v3 writes it
      // (its noise above 0 stays: the mean of such a column is a little above 0).
      if (expected < 0)
        EXPECT_LT(mean, 0.02) << json << ", column " << column;
      else
        EXPECT_NEAR(mean, expected, 0.01) << json << ", column " << column;
    }
  }
}

// Where every sample within a pixel's reach sees the same radiance, the
// splatted pixel is that radiance (the weights cancel), at the window's edge
// too: pixels outside the window are sampled for their neighbours.
TEST(RenderFilter, SplattingKeepsAFlatImageFlatToTheEdges) {
  const Scene scene = edge_scene(R"({"type": "gaussian", "mode": "splat"})");
  const Image image = render_scene(scene, 4, 2, CropWindow{0, 0, 6, 8});
  for (float v : image.rgb) EXPECT_NEAR(v, 1.0f, 1e-5f);
}

TEST(RenderFilter, SplattedImagesDoNotDependOnTheThreadCount) {
  const Scene scene = edge_scene(R"({"type": "mitchell", "mode": "splat"})");
  auto larger = [](RenderSettings& settings) {  // 20 tiles, so that threads take them out of order
    settings.width = 64;
    settings.height = 56;
  };
  const Image one = render_scene(scene, 8, 1, std::nullopt, larger), three = render_scene(scene, 8, 3, std::nullopt, larger);
  EXPECT_EQ(one.rgb, three.rgb);
}

// A crop is the same pixels of the whole image: its border pixels get their
// neighbours' samples from outside the window (to rounding: sums add in another order).
TEST(RenderFilter, ASplattedCropIsTheWholeImagesPixels) {
  const Scene scene = edge_scene(R"({"type": "gaussian", "mode": "splat"})");
  const Image whole = render_scene(scene, 8), crop = render_scene(scene, 8, 2, CropWindow{5, 2, 6, 4});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(crop.pixel(x, y)[c], whole.pixel(x + 5, y + 2)[c], 1e-5f) << x << "," << y;
}

// Parts of a splatted render (tiles dealt round, as over MPI) add their
// sums: the last part's image is then the whole one.
class SummingPart final : public RenderPartition {
 public:
  SummingPart(int part, int parts, std::vector<double>& total) : part_(part), parts_(parts), total_(total) {}
  int part() const override { return part_; }
  int parts() const override { return parts_; }
  double slowest_pass_seconds(double seconds) override { return seconds; }
  int next_pass_spp_of_first(int next_pass_spp) override { return next_pass_spp; }
  void sum_to_first(std::vector<double>& values) override {
    total_.resize(values.size(), 0.0);
    for (size_t i = 0; i < values.size(); ++i) total_[i] += values[i];
    values = total_;
  }

 private:
  int part_, parts_;
  std::vector<double>& total_;
};

TEST(RenderFilter, SplattedPartsAddUpToTheWholeImage) {
  const Scene scene = edge_scene(R"({"type": "gaussian", "mode": "splat"})");
  RenderOptions options;
  options.settings = scene.settings;
  options.settings.width = 40;  // more than one tile, so that the parts differ
  options.settings.spp = 4;
  options.threads = 2;
  const Image whole = render(scene, options);
  std::vector<double> total;
  Image last;
  for (int part = 0; part < 3; ++part) {
    SummingPart partition(part, 3, total);
    options.partition = &partition;
    last = render(scene, options);
  }
  ASSERT_EQ(last.rgb.size(), whole.rgb.size());
  for (size_t i = 0; i < whole.rgb.size(); ++i) EXPECT_NEAR(last.rgb[i], whole.rgb[i], 1e-5f) << i;
}

}  // namespace
}  // namespace safegi::render
