// Light strategies (LightStrategy): which lights next-event estimation sends
// its shadow rays to changes the noise, never the image; `all` sends each
// light its own number of rays.
#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// A diffuse plane lit by lights of very different power, as in Veach's MIS
// scene: a bright point light far off, a small dim sphere close to the plane,
// a quad emitter and a dim sky.
constexpr const char* kManyLights = R"json({
  "render": {"resolution": [24, 24], "integrator": "direct"},
  "camera": {"position": ["0 m", "4 m", "0.01 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "60 deg"},
  "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
  "shapes": [{"type": "quad", "material": "matte", "origin": ["-3 m", "0 m", "-3 m"],
              "edge_u": ["0 m", "0 m", "6 m"], "edge_v": ["6 m", "0 m", "0 m"]},
             {"type": "sphere", "center": ["-1 m", "0.3 m", "0 m"], "radius": "0.05 m", "emission": "40 W/(m2 sr)",
              "light_samples": 3},
             {"type": "quad", "origin": ["1 m", "1 m", "-0.5 m"], "edge_u": ["0.5 m", "0 m", "0 m"],
              "edge_v": ["0 m", "0 m", "1 m"], "emission": "2 W/(m2 sr)"}],
  "lights": [{"type": "point", "position": ["0 m", "30 m", "0 m"], "intensity": "900 W/sr"},
             {"type": "environment", "radiance": "0.05 W/(m2 sr)"}]})json";

struct Quadrants {
  Estimate parts[4];
};
// Each quadrant's mean of the red channel with its standard error.
Quadrants quadrant_estimates(const Image& image) {
  Quadrants q;
  for (int part = 0; part < 4; ++part) {
    Image quarter;
    quarter.width = image.width / 2;
    quarter.height = image.height / 2;
    for (int y = 0; y < quarter.height; ++y)
      for (int x = 0; x < quarter.width; ++x) {
        int sx = x + (part % 2) * quarter.width, sy = y + (part / 2) * quarter.height;
        for (int c = 0; c < 3; ++c) quarter.rgb.push_back(image.rgb[3 * (sy * image.width + sx) + c]);
      }
    q.parts[part] = channel_estimate(quarter, 0);
  }
  return q;
}

TEST(RenderLightStrategy, EveryStrategyConvergesToTheSameImage) {
  const LightStrategy strategies[] = {LightStrategy::power, LightStrategy::uniform, LightStrategy::spatial,
                                      LightStrategy::all};
  for (const char* integrator : {"direct", "path"}) {
    std::string text = kManyLights;
    text.replace(text.find("direct"), 6, integrator);
    std::vector<Quadrants> results;
    for (LightStrategy strategy : strategies)
      results.push_back(quadrant_estimates(
          render_text(text, 64, 2, std::nullopt, [&](RenderSettings& s) { s.light_strategy = strategy; })));
    for (size_t s = 1; s < results.size(); ++s)
      for (int part = 0; part < 4; ++part) {
        const Estimate& a = results[0].parts[part];
        const Estimate& b = results[s].parts[part];
        EXPECT_NEAR(b.mean, a.mean, 5 * std::hypot(a.standard_error, b.standard_error) + 1e-4 * a.mean)
            << integrator << ", " << name_of(strategies[s]) << ", quadrant " << part;
      }
  }
}

// `all` sends every light its light_samples (1 unless the scene says) per
// round: two point lights and a sphere light out of view that asks for 3, so
// 5 shadow rays at each point of the plane, which fills the view.
TEST(RenderLightStrategy, AllSendsEachLightItsOwnShadowRays) {
  const Scene scene = parse_scene(R"json({
    "render": {"resolution": [8, 8], "integrator": "direct"},
    "camera": {"position": ["0 m", "4 m", "0.01 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "20 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": ["-3 m", "0 m", "-3 m"],
                "edge_u": ["0 m", "0 m", "6 m"], "edge_v": ["6 m", "0 m", "0 m"]},
               {"type": "sphere", "center": ["-2.5 m", "1 m", "0 m"], "radius": "0.1 m", "emission": "4 W/(m2 sr)",
                "light_samples": 3}],
    "lights": [{"type": "point", "position": ["0 m", "30 m", "0 m"], "intensity": "900 W/sr"},
               {"type": "point", "position": ["2 m", "1 m", "0 m"], "intensity": "1 W/sr"}]})json",
                                  "test.json", SAFEGI_SCENES_DIR);
  for (int rounds : {1, 3}) {
    RenderOptions options;
    options.settings = scene.settings;
    options.settings.spp = 2;
    options.settings.light_strategy = LightStrategy::all;
    options.settings.light_samples = rounds;
    options.threads = 1;
    RenderStats stats;
    render(scene, options, &stats);
    EXPECT_EQ(stats.shadow_rays, stats.camera_rays * 5 * rounds) << rounds << " rounds";
  }
}

// Where a dim light is close and a bright one far, choosing by power sends
// almost every ray to the far one; the spatial choice and `all` do not. The
// small sphere's neighbourhood at 4 samples per pixel, against each
// strategy's own 256: less noise.
TEST(RenderLightStrategy, SpatialAndAllLowerTheNoiseNearADimLight) {
  std::string text = kManyLights;
  // A camera close above the plane beside the small sphere (out of view).
  for (auto [from, to] : {std::pair{R"("position": ["0 m", "4 m", "0.01 m"])", R"("position": ["-0.6 m", "1 m", "0.01 m"])"},
                          std::pair{R"("look_at": ["0 m", "0 m", "0 m"])", R"("look_at": ["-0.6 m", "0 m", "0 m"])"},
                          std::pair{R"("fov": "60 deg")", R"("fov": "30 deg")"}})
    text.replace(text.find(from), std::string_view(from).size(), to);
  auto noise = [&](LightStrategy strategy) {
    Image image = render_text(text, 4, 2, std::nullopt, [&](RenderSettings& s) { s.light_strategy = strategy; });
    Image reference = render_text(text, 256, 2, std::nullopt, [&](RenderSettings& s) { s.light_strategy = strategy; });
    double squared = 0;
    for (size_t i = 0; i < image.rgb.size(); ++i) squared += std::pow(image.rgb[i] - reference.rgb[i], 2);
    return std::sqrt(squared / static_cast<double>(image.rgb.size()));
  };
  const double by_power = noise(LightStrategy::power);
  // Measured: power 0.91, spatial 0.043, all (3 rays for the sphere) 0.0028.
  EXPECT_LT(noise(LightStrategy::spatial), 0.1 * by_power);
  EXPECT_LT(noise(LightStrategy::all), 0.1 * by_power);
}

}  // namespace
}  // namespace safegi::render
