// The photon-mapping integrator (a caustic photon map beside the path tracer)
// against closed forms and the path tracer: a white furnace around a glass
// sphere (no kernel bias in a uniform field: the estimate checks the photons'
// flux, the kernel's normalisation and that the camera paths leave the
// caustics to the map), the same seen through a translucent sheet (caustics
// that arrive on the sheet's far side), and the caustic of a glass sphere on a floor, which
// the path tracer reaches only slowly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// Inside a closed emitting sphere of albedo a, L = Le / (1 − a) everywhere, a
// glass ball in it or not: glass only redirects a uniform field. Through the
// ball the camera paths find the emitter behind specular bounces after a
// diffuse vertex; those are the caustic map's, so a missing or doubled map
// would show. `more_materials` and `more_shapes` join the scene's lists;
// `crop` is where the image is measured (all of it by default), with `spp`.
void expect_white_furnace_with_its_caustics(const std::string& more_materials = "", const std::string& more_shapes = "",
                                            std::optional<CropWindow> crop = std::nullopt, int spp = 32) {
  for (double albedo : {0.5, 0.8}) {
    std::string text = R"json({
      "render": {"resolution": [16, 16], "integrator": "photon", "max_depth": 400, "photons": 100000},
      "camera": {"position": ["0 m", "0 m", "0.5 m"], "look_at": ["0 m", "0 m", "-1 m"], "up": [0, 1, 0], "fov": "120 deg"},
      "materials": {"grey": {"type": "lambert", "reflectance": ALBEDO}, "glass": {"type": "glass", "ior": 1.5}MATERIALS},
      "shapes": [{"type": "sphere", "material": "grey", "center": ["0.1 m", "0.2 m", "0 m"], "radius": "1 m",
                  "emission": "0.5 W/(m2 sr)", "two_sided": true},
                 {"type": "sphere", "material": "glass", "center": ["0 m", "0 m", "-0.2 m"], "radius": "0.4 m"}SHAPES]})json";
    text.replace(text.find("ALBEDO"), 6, std::to_string(albedo));
    text.replace(text.find("MATERIALS"), 9, more_materials);
    text.replace(text.find("SHAPES"), 6, more_shapes);
    Image image = render_text(text, spp, 2, crop);
    const double expected = 0.5 / (1 - albedo);
    for (int c = 0; c < 3; ++c) {
      Estimate e = channel_estimate(image, c);
      // One photon map serves every pixel, so a pixel's spread understates its
      // error; 2 % is ~3 times what the photons' count leaves.
      EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 0.02 * expected) << albedo;
      EXPECT_LT(e.standard_error, 0.01 * expected) << albedo;
    }
    // Leaving out the map (the camera paths with their caustics dropped) is
    // clearly darker: the map carries a share well beyond the tolerance above.
    Scene scene = parse_scene(text, "test.json", ".");
    scene.settings.photons = 1;
    double without = channel_estimate(render_scene(scene, spp, 2, crop), 0).mean;
    EXPECT_LT(without, 0.95 * expected) << albedo;
  }
}

TEST(RenderPhotons, WhiteFurnaceAroundAGlassSphere) { expect_white_furnace_with_its_caustics(); }

// A lossless translucent sheet (Kd 1, reflect + transmit 1, no glossy part)
// between the camera and the glass ball keeps the field uniform. Its caustics
// land on its back, which the camera does not see: the light they bring
// reaches the camera through the sheet, from photons on the other side of
// the surface the estimate is made on (measured where the sheet fills the image).
TEST(RenderPhotons, WhiteFurnaceThroughATranslucentSheet) {
  expect_white_furnace_with_its_caustics(
      R"json(, "paper": {"type": "translucent", "diffuse": 1, "specular": 0, "reflect": 0.4, "transmit": 0.6,
                         "alpha": 0.3})json",
      R"json(, {"type": "quad", "material": "paper", "origin": ["-0.3 m", "-0.3 m", "0.3 m"],
                "edge_u": ["0.6 m", "0 m", "0 m"], "edge_v": ["0 m", "0.6 m", "0 m"]})json",
      CropWindow{4, 4, 8, 8}, 256);
}

// With nothing specular there are no caustics: the photon integrator is the path tracer, bit for bit.
TEST(RenderPhotons, WithoutSpecularSurfacesItIsThePathTracer) {
  const std::filesystem::path folder = std::filesystem::path(SAFEGI_SCENES_DIR) / "cornell-box";
  std::string text = read_text(folder / "cornell-box.json");
  Image path = render_text(text, 4, 2, CropWindow{100, 100, 24, 24}, {}, folder);
  Image photon = render_text(text, 4, 2, CropWindow{100, 100, 24, 24},
                             [](RenderSettings& s) { s.integrator = IntegratorType::photon, s.photons = 1000; }, folder);
  ASSERT_EQ(path.rgb.size(), photon.rgb.size());
  EXPECT_EQ(std::memcmp(path.rgb.data(), photon.rgb.data(), path.rgb.size() * sizeof(float)), 0);
}

// A glass sphere 0.7 m above a lambertian floor, lit by a spherical light
// straight above it, focuses light into the floor under it, where the sphere's
// shadow leaves no direct light. The photon map's estimate of that patch
// (300000 photons, 3 cm kernel) agrees with the path tracer at 2048 samples
// per pixel (its standard error there ~0.6 %, measured over seeds) within 4 %.
TEST(RenderPhotons, CausticUnderAGlassSphereMatchesThePathTracer) {
  const std::string scene = R"json({
    "render": {"resolution": [64, 64], "integrator": "path", "max_depth": 16, "photons": 300000, "photon_radius": "3 cm"},
    "camera": {"position": ["0 m", "1 m", "3 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "30 deg"},
    "materials": {"floor": {"type": "lambert", "reflectance": 0.8}, "glass": {"type": "glass", "ior": 1.5}},
    "shapes": [
      {"type": "quad", "material": "floor", "origin": ["-3 m", "0 m", "-3 m"], "edge_u": ["0 m", "0 m", "6 m"],
       "edge_v": ["6 m", "0 m", "0 m"]},
      {"type": "sphere", "material": "glass", "center": ["0 m", "1.2 m", "0 m"], "radius": "0.5 m"},
      {"type": "sphere", "center": ["0 m", "4 m", "0 m"], "radius": "0.4 m", "emission": "100 W/(m2 sr)"}]})json";
  const CropWindow caustic{24, 24, 16, 16};
  auto with = [](IntegratorType integrator) { return [=](RenderSettings& s) { s.integrator = integrator; }; };
  double path = channel_estimate(render_text(scene, 2048, 2, caustic, with(IntegratorType::path)), 0).mean;
  double photon = channel_estimate(render_text(scene, 4, 2, caustic, with(IntegratorType::photon)), 0).mean;
  double direct = channel_estimate(render_text(scene, 64, 2, caustic, with(IntegratorType::direct)), 0).mean;
  EXPECT_NEAR(photon, path, 0.04 * path);
  EXPECT_LT(direct, 0.1 * path);  // the patch is lit by the caustic alone
  EXPECT_GT(path, 1.0);           // and brightly: ~1.37 W/(m2 sr)
}

}  // namespace
}  // namespace safegi::render
