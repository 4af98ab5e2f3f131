// Whole renders of pbrt-v3 scenes whose answer pbrt-v3's rules give in closed
// form: Film "scale" multiplies the image; a closed two-sided emitter without a
// surface (Material "none") lights the scene through its near side only, as
// pbrt-v3's shadow rays stop there; uber's opacity lets the rest of the light
// straight through.
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

// A matte floor (Kd 0.5) at y = 0 seen at its origin through a 1° view, lit
// by `emitter` above it alone (maxdepth 1: direct light only).
Scene floor_under(const std::string& integrator, const std::string& emitter) {
  return pbrt_scene("LookAt 0 1.5 3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 1\n"
                    "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                    "Integrator \"" + integrator + "\" \"integer maxdepth\" 1\nWorldBegin\n"
                    "AttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
                    "Shape \"trianglemesh\" \"point P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10] \"integer indices\" [0 1 2 0 2 3]\n"
                    "AttributeEnd\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [2 2 2] \"bool twosided\" \"true\"\n"
                    "Material \"none\"\nTranslate 0 3 0\n" + emitter + "\nAttributeEnd\nWorldEnd\n");
}

// A cube of side 2 about the origin, its 12 triangles.
const char* const kCube =
    "Shape \"trianglemesh\" \"point P\" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1] "
    "\"integer indices\" [0 1 2 0 2 3  4 6 5 4 7 6  0 4 5 0 5 1  3 2 6 3 6 7  0 3 7 0 7 4  1 5 6 1 6 2]";

// The irradiance at the origin, facing +y, from a square of radiance `radiance`
// and side `side` centred `height` above it, parallel to the floor (midpoint rule).
double irradiance_under_square(double radiance, double side, double height) {
  constexpr int kCells = 1000;
  const double cell = side / kCells;
  double sum = 0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const double x = -side / 2 + (i + 0.5) * cell, z = -side / 2 + (j + 0.5) * cell;
      const double r2 = x * x + z * z + height * height;
      sum += height * height / (r2 * r2);  // cos θ cos θ' / r²
    }
  return radiance * sum * cell * cell;
}

// pbrt-v3's path and directlighting test shadow rays against every surface:
// a closed two-sided emitter of material "none" lights the floor from its
// near side only (its far side, whose inside faces the floor, is hidden
// behind it), though the camera would see both. The floor's radiance is
// Kd/π · E, with E from the near side alone: a sphere of radius 1 centred 3
// above, π L (1/3)²; the cube's bottom face, 2 above.
TEST(RenderPbrt, ClosedEmittersWithoutASurfaceHideTheirFarSide) {
  const double sphere_irradiance = kPiD * 2 / 9;
  const double cube_irradiance = irradiance_under_square(2, 2, 2);
  for (const char* integrator : {"path", "directlighting"}) {
    for (const auto& [emitter, irradiance] : {std::pair<std::string, double>{"Shape \"sphere\" \"float radius\" 1", sphere_irradiance},
                                              std::pair<std::string, double>{kCube, cube_irradiance}}) {
      const Scene scene = floor_under(integrator, emitter);
      const double expected = 0.5 / kPiD * irradiance;
      for (const Knobs& knobs : estimator_knobs()) {
        const Estimate estimate = channel_estimate(render_scene(scene, 256, 2, std::nullopt, knobs.apply), 1);
        EXPECT_NEAR(estimate.mean, expected, 4 * estimate.standard_error + 5e-3 * expected)
            << integrator << ", " << emitter.substr(0, 20) << ", " << knobs.name;
      }
    }
  }
}

// An uber sheet (Kd, no Ks) filling the view in a uniform sky of radiance 1:
// its lobes times the opacity reflect opacity · Kd of the sky above (a
// Lambertian surface under a uniform hemisphere reflects Kd · L), and 1 −
// opacity of the sky behind comes straight through: opacity · Kd + 1 − opacity,
// per channel.
TEST(RenderPbrt, UberOpacityLetsTheRestOfTheLightStraightThrough) {
  const double opacity[3] = {0.2, 0.5, 0.8};
  for (double kd : {0.5, 0.0}) {
    const std::string k = std::to_string(kd);
    const Scene scene = pbrt_scene(
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 10\n"
        "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "Material \"uber\" \"rgb Kd\" [" + k + " " + k + " " + k + "] \"rgb Ks\" [0 0 0] \"rgb opacity\" [0.2 0.5 0.8]\n"
        "Shape \"trianglemesh\" \"point P\" [-10 -10 0  10 -10 0  10 10 0  -10 10 0] \"integer indices\" [0 1 2 0 2 3]\n"
        "WorldEnd\n");
    for (const Knobs& knobs : estimator_knobs()) {
      const Image image = render_scene(scene, 256, 2, std::nullopt, knobs.apply);
      for (int c = 0; c < 3; ++c) {
        const double expected = opacity[c] * kd + 1 - opacity[c];
        const Estimate estimate = channel_estimate(image, c);
        EXPECT_NEAR(estimate.mean, expected, 4 * estimate.standard_error + 2e-3 * expected)
            << "Kd " << kd << ", channel " << c << ", " << knobs.name;
      }
    }
  }
}

}  // namespace
}  // namespace safegi::render
