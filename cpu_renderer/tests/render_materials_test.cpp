// Whole renders of the environment light, glass, plastic, metal and textures against
// closed forms: furnaces (a convex object in a constant environment reflects
// exactly its albedo, glass exactly everything), a slab's multiple
// reflections, an environment map's irradiance, and texels seen through a
// camera.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "materials/bsdf.hpp"
#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;
namespace fs = std::filesystem;

// A camera at distance `d` on +z looking at the origin.
std::string camera_on_z(double d, double fov_degrees, int size, const std::string& integrator = "path",
                        int max_depth = 65) {
  return "\"render\": {\"resolution\": [" + std::to_string(size) + ", " + std::to_string(size) + "], \"integrator\": \"" +
         integrator + "\", \"max_depth\": " + std::to_string(max_depth) + "},\n" +
         "\"camera\": {\"position\": [\"0 m\", \"0 m\", \"" + std::to_string(d) +
         " m\"], \"look_at\": [\"0 m\", \"0 m\", \"0 m\"], \"up\": [0, 1, 0], \"fov\": \"" + std::to_string(fov_degrees) +
         " deg\"}";
}

// A convex lambertian sphere in a constant environment L sees nothing but the
// environment: every pixel on it is ρ L, every other pixel L.
TEST(RenderMaterials, WhiteFurnaceWithTheEnvironmentLightIsTheAlbedo) {
  const double rho = 0.6, sky = 1.5;
  std::string scene = "{" + camera_on_z(4, 40, 24) + R"json(,
    "materials": {"matte": {"type": "lambert", "reflectance": 0.6}},
    "shapes": [{"type": "sphere", "material": "matte", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
    "lights": [{"type": "environment", "radiance": "1.5 W/(m2 sr)"}]})json";
  for (const char* integrator : {"path", "direct"})
    for (const Knobs& knobs : estimator_knobs()) {
      auto adjust = [&](RenderSettings& s) {
        knobs.apply(s);
        s.integrator = std::string(integrator) == "path" ? IntegratorType::path : IntegratorType::direct;
      };
      Image inside = render_text(scene, 32, 2, CropWindow{8, 8, 8, 8}, adjust);  // on the sphere
      for (int c = 0; c < 3; ++c) {
        Estimate e = channel_estimate(inside, c);
        EXPECT_NEAR(e.mean, rho * sky, 5 * e.standard_error + 1e-6) << integrator << ", " << knobs.name;
        EXPECT_LT(e.standard_error, 0.01 * rho * sky) << integrator << ", " << knobs.name;
      }
      Image corner = render_text(scene, 4, 1, CropWindow{0, 0, 2, 2}, adjust);  // the sky itself
      for (float v : corner.rgb) EXPECT_FLOAT_EQ(v, static_cast<float>(sky));
    }
}

// A lat-long map whose upper rows are bright (1) and lower rows dim (0.2),
// bilinear between the row centres, lights a lambertian plane whose normal is
// the map's pole: L = ρ/π · E, E = 2π ∫ L(θ) cos θ sin θ dθ over the upper
// hemisphere. The map is rotated so that its pole is world +y, the floor's normal.
TEST(RenderMaterials, EnvironmentMapLightsAPlaneByItsIrradiance) {
  fs::path directory = fs::temp_directory_path() / ("safegi-render-envmap-" + std::to_string(::getpid()));
  fs::create_directories(directory);
  Image map{8, 4, {}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) map.rgb.insert(map.rgb.end(), 3, y < 2 ? 1.0f : 0.2f);
  write_pfm(directory / "sky.pfm", map);
  auto profile = [](double theta) {  // the map's radiance at polar angle θ
    double v = theta / kPiD;
    return v <= 0.375 ? 1.0 : v >= 0.625 ? 0.2 : 1.0 - 0.8 * (v - 0.375) / 0.25;
  };
  double irradiance = 0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    double theta = (i + 0.5) * (kPiD / 2) / steps;
    irradiance += 2 * kPiD * profile(theta) * std::cos(theta) * std::sin(theta) * (kPiD / 2) / steps;
  }
  const double rho = 0.5, expected = rho / kPiD * irradiance;
  std::string scene = R"json({"render": {"resolution": [16, 16], "integrator": "path", "max_depth": 1},
    "camera": {"position": ["0 m", "3 m", "0 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 0, -1], "fov": "30 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": ["-50 m", "0 m", "-50 m"],
                "edge_u": ["0 m", "0 m", "100 m"], "edge_v": ["100 m", "0 m", "0 m"]}],
    "lights": [{"type": "environment", "file": "sky.pfm",
                "transform": [{"rotate": {"axis": [1, 0, 0], "angle": "-90 deg"}}]}]})json";
  for (const Knobs& knobs : estimator_knobs()) {
    Image image = render_text(scene, 64, 2, std::nullopt, knobs.apply, directory);
    Estimate e = channel_estimate(image, 1);
    EXPECT_NEAR(e.mean, expected, 5 * e.standard_error) << knobs.name;
    EXPECT_LT(e.standard_error, 0.01 * expected) << knobs.name;
  }
  fs::remove_all(directory);
}

// Glass (no tint) in a constant environment only redirects light: every path
// leaves with throughput exactly 1 (Fresnel's choice and its probability
// cancel; the 1/η² of entering cancels the η² of leaving), so every pixel is
// the environment's radiance, however the sphere bends it.
TEST(RenderMaterials, GlassSphereInAWhiteFurnaceIsInvisible) {
  for (const char* ior : {"1.5", "2.4", "0.75"}) {
    std::string scene = "{" + camera_on_z(4, 40, 16, "path", 400) + R"json(,
      "materials": {"glass": {"type": "glass", "ior": )json" + std::string(ior) + R"json(}},
      "shapes": [{"type": "sphere", "material": "glass", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
      "lights": [{"type": "environment", "radiance": "2 W/(m2 sr)"}]})json";
    Image image = render_text(scene, 16, 2, std::nullopt, [](RenderSettings& s) { s.russian_roulette = false; });
    for (float v : image.rgb) EXPECT_NEAR(v, 2.0f, 2e-4f) << ior;
  }
}

// A glass slab seen head-on in front of an emitter transmits, over all its
// internal reflections, T = (1 − R)² Σ R^2k = (1 − R)/(1 + R) with R the
// normal-incidence Fresnel reflectance ((n − 1)/(n + 1))²; for n = 2.4 that is
// 0.7100, clearly apart from the single pass (1 − R)² = 0.6896.
// A diamond slab 0.2 m thick between the camera and an emitter of 3 W/(m² sr).
std::string diamond_slab(int size, const std::string& integrator) {
  return "{" + camera_on_z(5, 2, size, integrator, 400) + R"json(,
    "materials": {"diamond": {"type": "glass", "ior": 2.4}},
    "shapes": [
      {"type": "quad", "material": "diamond", "origin": ["-2 m", "-2 m", "0.1 m"], "edge_u": ["4 m", "0 m", "0 m"], "edge_v": ["0 m", "4 m", "0 m"]},
      {"type": "quad", "material": "diamond", "origin": ["-2 m", "-2 m", "-0.1 m"], "edge_u": ["0 m", "4 m", "0 m"], "edge_v": ["4 m", "0 m", "0 m"]},
      {"type": "quad", "origin": ["-2 m", "-2 m", "-1 m"], "edge_u": ["4 m", "0 m", "0 m"], "edge_v": ["0 m", "4 m", "0 m"],
       "emission": "3 W/(m2 sr)"}]})json";
}

TEST(RenderMaterials, GlassSlabTransmitsOneMinusROverOnePlusR) {
  const double n = 2.4, r = (n - 1) * (n - 1) / ((n + 1) * (n + 1)), expected = (1 - r) / (1 + r), emission = 3;
  std::string scene = diamond_slab(32, "path");
  Image image = render_text(scene, 256, 2, std::nullopt, [](RenderSettings& s) { s.russian_roulette = false; });
  Estimate e = channel_estimate(image, 0);
  EXPECT_NEAR(e.mean, expected * emission, 5 * e.standard_error);
  EXPECT_LT(5 * e.standard_error, 0.01 * expected * emission);  // resolves the 3 % from the single pass
}

// Direct lighting follows both of glass's lobes (pbrt-v3's directlighting and
// whitted do), so the same slab at 1 spp is the series itself in every pixel,
// with no Fresnel choice to make it noisy (it fails if one lobe is chosen).
TEST(RenderMaterials, DirectLightingFollowsBothLobesOfGlass) {
  const double n = 2.4, r = (n - 1) * (n - 1) / ((n + 1) * (n + 1)), expected = 3 * (1 - r) / (1 + r);
  std::string scene = diamond_slab(8, "direct");
  Image image = render_text(scene, 1, 2, std::nullopt, [](RenderSettings& s) { s.russian_roulette = false; });
  for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_NEAR(image.rgb[i], expected, 1e-4 * expected) << i;
}

// A floor (normal +z) of `material_json` under a constant environment of
// 1 W/(m² sr), seen `view` radians off its normal through a 0.5° camera,
// direct light only: each pixel is the material's directional albedo there.
std::string floor_in_a_furnace(const std::string& material_json, double view) {
  std::string position = "[\"" + std::to_string(4 * std::sin(view)) + " m\", \"0 m\", \"" + std::to_string(4 * std::cos(view)) + " m\"]";
  return R"json({"render": {"resolution": [8, 8], "integrator": "path", "max_depth": 1},
      "camera": {"position": )json" + position + R"json(, "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "0.5 deg"},
      "materials": {"floor": )json" + material_json + R"json(},
      "shapes": [{"type": "quad", "material": "floor", "origin": ["-50 m", "-50 m", "0 m"],
                  "edge_u": ["100 m", "0 m", "0 m"], "edge_v": ["0 m", "100 m", "0 m"]}],
      "lights": [{"type": "environment", "radiance": "1 W/(m2 sr)"}]})json";
}

// ∫ f(ωo, ωi) cos θi dωi per channel by the midpoint rule, ωo `view` off the normal.
glm::dvec3 directional_albedo(const Material& material, double view) {
  Bsdf bsdf(material);
  DirectionShading wo(static_cast<Real>(std::sin(view)), 0, static_cast<Real>(std::cos(view)));
  glm::dvec3 albedo(0.0);
  const int theta_steps = 1500, phi_steps = 180;
  for (int i = 0; i < theta_steps; ++i) {
    double theta = (i + 0.5) * (kPiD / 2) / theta_steps;
    for (int j = 0; j < phi_steps; ++j) {
      double phi = (j + 0.5) * 2 * kPiD / phi_steps;
      DirectionShading wi(static_cast<Real>(std::sin(theta) * std::cos(phi)),
                          static_cast<Real>(std::sin(theta) * std::sin(phi)), static_cast<Real>(std::cos(theta)));
      albedo += glm::dvec3(sg::raw(bsdf.eval(wo, wi))) * std::cos(theta) * std::sin(theta) *
                (kPiD / 2 / theta_steps) * (2 * kPiD / phi_steps);
    }
  }
  return albedo;
}

// Every channel of a render of floor_in_a_furnace against `expected`, under
// every estimator knob (`only_with_mis`: those that weight light and BSDF
// samples by MIS): within 5 standard errors and 2e-3 relative (the
// quadrature's error), with a standard error under 1 %.
void expect_floor_reflects(const std::string& material_json, double view_degrees, const glm::dvec3& expected,
                           bool only_with_mis = false) {
  std::string scene = floor_in_a_furnace(material_json, view_degrees * kPiD / 180);
  for (const Knobs& knobs : estimator_knobs()) {
    RenderSettings chosen;
    knobs.apply(chosen);
    if (only_with_mis && !chosen.mis) continue;
    Image image = render_text(scene, 512, 2, std::nullopt, knobs.apply);
    for (int c = 0; c < 3; ++c) {
      Estimate e = channel_estimate(image, c);
      EXPECT_NEAR(e.mean, expected[c], 5 * e.standard_error + 2e-3 * expected[c])
          << material_json << " at " << view_degrees << " deg, channel " << c << ", " << knobs.name;
      EXPECT_LT(e.standard_error, 0.01 * expected[c]) << view_degrees << ", channel " << c << ", " << knobs.name;
    }
  }
}

// Plastic and rough copper seen at one angle in a constant environment:
// the pixel is L times the material's directional albedo, which a quadrature
// of its BRDF gives.
TEST(RenderMaterials, PlasticAndRoughMetalReflectTheirDirectionalAlbedo) {
  const Material plastic{PlasticMaterial{TexturedReflectance{Reflectance(0.5f, 0.3f, 0.2f)}, Reflectance(0.4f), 0.15f}};
  const Material copper{ConductorMaterial{IndexSpectrum(0.2f, 0.92f, 1.1f), IndexSpectrum(3.9f, 2.45f, 2.14f), 0.15f}};
  for (double view_degrees : {0.0, 60.0}) {
    expect_floor_reflects(R"j({"type": "plastic", "diffuse": [0.5, 0.3, 0.2], "specular": 0.4, "alpha": 0.15})j",
                          view_degrees, directional_albedo(plastic, view_degrees * kPiD / 180));
    expect_floor_reflects(
        R"j({"type": "conductor", "eta": [0.2, 0.92, 1.1], "k": [3.9, 2.45, 2.14], "alpha": 0.15})j", view_degrees,
        directional_albedo(copper, view_degrees * kPiD / 180));
  }
}

// pbrt-v3's substrate likewise: FresnelBlend is not energy conserving (no
// white furnace), so the pixel is checked against the quadrature of its BRDF.
TEST(RenderMaterials, SubstrateReflectsItsDirectionalAlbedo) {
  const Material substrate{SubstrateMaterial{TexturedReflectance{Reflectance(0.5f, 0.3f, 0.2f)}, Reflectance(0.4f), 0.15f}};
  for (double view_degrees : {0.0, 60.0})
    expect_floor_reflects(R"j({"type": "substrate", "diffuse": [0.5, 0.3, 0.2], "specular": 0.4, "alpha": 0.15})j",
                          view_degrees, directional_albedo(substrate, view_degrees * kPiD / 180));
}

// A nearly smooth metal (α = 0.001, pbrt-v3's floor) reflects the
// environment with its Fresnel reflectance at the viewing angle: masking
// takes less than 1e-5 there, so the pixel is F(θ; η, k) per channel; at
// normal incidence ((η − 1)² + k²) / ((η + 1)² + k²). Only the knobs with
// MIS: without it the environment's light reaches this lobe only through light
// samples, which fall into its ~π α² = 3e-6 sr about once in a million (an
// unbiased estimate that would need a million times the samples); the rough
// metal above holds under every knob.
TEST(RenderMaterials, SmoothMetalReflectsItsFresnelReflectance) {
  const double eta[] = {0.2, 0.92, 1.1}, k[] = {3.9, 2.45, 2.14};
  for (double view_degrees : {0.0, 60.0}) {
    glm::dvec3 fresnel;
    for (int c = 0; c < 3; ++c)
      fresnel[c] = fresnel_conductor(static_cast<Real>(std::cos(view_degrees * kPiD / 180)), static_cast<Real>(eta[c]),
                                     static_cast<Real>(k[c]));
    for (int c = 0; c < 3 && view_degrees == 0; ++c)
      EXPECT_NEAR(fresnel[c], ((eta[c] - 1) * (eta[c] - 1) + k[c] * k[c]) / ((eta[c] + 1) * (eta[c] + 1) + k[c] * k[c]),
                  1e-6);
    expect_floor_reflects(R"j({"type": "conductor", "eta": [0.2, 0.92, 1.1], "k": [3.9, 2.45, 2.14], "alpha": 0.001})j",
                          view_degrees, fresnel, true);
  }
}

// A textured floor under a point light, seen head-on so that each pixel covers
// a known square of (u, v): the image over the untextured one's is the
// texture, bilinearly interpolated, at the pixel's centre (bilinear is linear
// in u and in v inside each square of four texel centres, and no pixel
// straddles one: its average is its centre's value).
class TexturedFloor : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("safegi-render-texture-" + std::to_string(::getpid()));
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // The floor [0, 1]² (u along x, v along y) fills a size × size image.
  std::string scene(const std::string& reflectance, int size) const {
    return R"json({"render": {"resolution": [)json" + std::to_string(size) + ", " + std::to_string(size) + R"json(], "integrator": "direct"},
      "camera": {"position": ["0.5 m", "0.5 m", "4 m"], "look_at": ["0.5 m", "0.5 m", "0 m"], "up": [0, 1, 0],
                 "fov": ")json" + std::to_string(2 * std::atan(0.5 / 4) * 180 / kPiD) + R"json( deg"},
      "textures": {"smooth": {"type": "image", "file": "smooth.pfm", "filter": "bilinear", "wrap": "clamp"},
                   "checker": {"type": "image", "file": "checker.pfm", "filter": "trilinear"},
                   "ewa": {"type": "image", "file": "checker.pfm", "filter": "ewa", "max_anisotropy": 4},
                   "aliased": {"type": "image", "file": "checker.pfm", "filter": "bilinear"}},
      "materials": {"floor": {"type": "lambert", "reflectance": )json" + reflectance + R"json(}},
      "shapes": [{"type": "quad", "material": "floor", "origin": ["0 m", "0 m", "0 m"],
                  "edge_u": ["1 m", "0 m", "0 m"], "edge_v": ["0 m", "1 m", "0 m"]}],
      "lights": [{"type": "point", "position": ["0.5 m", "0.5 m", "2 m"], "intensity": "10 W/sr"}]})json";
  }

  fs::path directory_;
};

TEST_F(TexturedFloor, PixelsShowTheBilinearTexture) {
  // 4×4 texels, value 0.1 + 0.05 x + 0.2 y^2 (file rows top to bottom: y = 3 first).
  Image smooth{4, 4, {}};
  auto value = [](int x, int y) { return 0.1f + 0.05f * x + 0.2f * y * y / 9.0f; };
  for (int row = 0; row < 4; ++row)
    for (int x = 0; x < 4; ++x) smooth.rgb.insert(smooth.rgb.end(), 3, value(x, 3 - row));
  write_pfm(directory_ / "smooth.pfm", smooth);
  write_pfm(directory_ / "checker.pfm", Image{1, 1, {0, 0, 0}});
  MipMap expected_map(Image(smooth), TextureWrap::clamp);
  const int size = 32;
  Image textured = render_text(scene(R"({"texture": "smooth"})", size), 64, 2, std::nullopt, {}, directory_);
  Image plain = render_text(scene("1", size), 64, 2, std::nullopt, {}, directory_);
  double worst = 0;
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      // expected_map keeps the file's rows (row 0 on top): the image's rows in
      // order, since the loader's flip puts the file's top row at v = 1.
      Real s = (px + Real(0.5)) / size, t = (py + Real(0.5)) / size;
      double texel = sg::raw(expected_map.bilinear(0, s, t)).r;
      worst = std::max(worst, std::abs(textured.pixel(px, py)[0] / plain.pixel(px, py)[0] / texel - 1));
    }
  EXPECT_LT(worst, 2e-3);
}

// A checker of single texels (64×64) seen at 16×16 pixels: each pixel covers
// 4×4 texels. Trilinear filtering reads level 2, where the checker is grey
// (0.5) everywhere; bilinear on level 0 aliases, four camera samples per pixel
// landing on black or white texels. EWA, over the footprint's circle here,
// reads the same level.
TEST_F(TexturedFloor, MipMapsAverageWhatAPixelCovers) {
  Image checker{64, 64, {}};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) checker.rgb.insert(checker.rgb.end(), 3, (x + y) % 2 ? 1.0f : 0.0f);
  write_pfm(directory_ / "checker.pfm", checker);
  write_pfm(directory_ / "smooth.pfm", Image{1, 1, {0, 0, 0}});
  const int size = 16;
  Image plain = render_text(scene("1", size), 4, 2, std::nullopt, {}, directory_);
  Image filtered = render_text(scene(R"({"texture": "checker"})", size), 4, 2, std::nullopt, {}, directory_);
  Image aliased = render_text(scene(R"({"texture": "aliased"})", size), 4, 2, std::nullopt, {}, directory_);
  Image ewa = render_text(scene(R"({"texture": "ewa"})", size), 4, 2, std::nullopt, {}, directory_);
  double filtered_worst = 0, aliased_worst = 0, ewa_worst = 0;
  for (size_t i = 0; i < plain.rgb.size(); ++i) {
    filtered_worst = std::max(filtered_worst, std::abs(filtered.rgb[i] / plain.rgb[i] - 0.5));
    aliased_worst = std::max(aliased_worst, std::abs(aliased.rgb[i] / plain.rgb[i] - 0.5));
    ewa_worst = std::max(ewa_worst, std::abs(ewa.rgb[i] / plain.rgb[i] - 0.5));
  }
  EXPECT_LT(filtered_worst, 1e-3);
  EXPECT_LT(ewa_worst, 1e-3);
  EXPECT_GT(aliased_worst, 0.1);
}

}  // namespace
}  // namespace safegi::render
