// Whole renders of pbrt-v3 scenes whose answer pbrt-v3's rules give in closed
// form: Film "scale" multiplies the image.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_test_support.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

Scene pbrt_scene(const std::string& text) {
  PbrtImportOptions options;
  options.metres_per_unit = 1;
  PbrtScene scene = parse_pbrt_scene(text, "scene.pbrt", ".", options);
  return std::move(scene.scene);
}

// A uniform sky of radiance 0.5 fills every pixel: the image mean is 0.5 × the
// film's scale, exactly, through the plain box and through splatted filters alike.
TEST(RenderPbrt, FilmScaleMultipliesTheImage) {
  for (const std::string filter : {"", "PixelFilter \"gaussian\"\n"}) {
    for (double scale : {1.0, 3.0, 0.25}) {
      const Scene scene = pbrt_scene("Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8 \"float scale\" " +
                                     std::to_string(scale) + "\n" + filter +
                                     "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\nWorldEnd\n");
      const Image image = render_scene(scene, 4);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(channel_estimate(image, c).mean, 0.5 * scale, 1e-6 * scale) << "scale " << scale << " " << filter;
    }
  }
}

}  // namespace
}  // namespace safegi::render
