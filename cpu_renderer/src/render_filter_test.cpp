// Pixel filters (pixel_filter.hpp) in whole renders: an emitter's straight
// edge seen by an orthographic camera, each column of pixels against the share
// of the filter's weight that lies on the emitter's side.
#include <algorithm>

#include "pixel_filter.hpp"
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

TEST(RenderFilter, AnEdgeIsBlurredByTheFilter) {
  const std::pair<const char*, PixelFilterType> filters[] = {
      {R"({"type": "box"})", PixelFilterType::box},
      {R"({"type": "box", "radius": [1.5, 1.5]})", PixelFilterType::box},
      {R"({"type": "triangle"})", PixelFilterType::triangle},
      {R"({"type": "gaussian"})", PixelFilterType::gaussian},
      {R"({"type": "mitchell"})", PixelFilterType::mitchell},
      {R"({"type": "sinc"})", PixelFilterType::sinc}};
  for (auto [json, type] : filters) {
    std::string text = kEdge;
    text.replace(text.find("FILTER"), 6, json);
    const Scene scene = parse_scene(text, "test.json", SAFEGI_SCENES_DIR);
    const PixelFilter& filter = scene.settings.filter;
    ASSERT_EQ(filter.type, type);
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

}  // namespace
}  // namespace safegi::render
