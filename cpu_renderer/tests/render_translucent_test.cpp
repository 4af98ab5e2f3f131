// Whole renders of pbrt-v3's translucent material against closed forms: a
// lossless one in a white furnace (reflect + transmit = 1, Kd = 1: every pixel
// is the environment's radiance), light that reaches the camera only through
// the surface (a distant light behind it, diffuse and glossy, seen from either
// side of the interface; an area light behind it, by both MIS strategies),
// and caustics through it in the photon map.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// Seen from outside or from inside, every point scatters exactly what reaches
// it (Kd = 1, reflect + transmit = 1 per channel, no glossy part): a
// uniform field stays uniform, inside the sphere too. The lobe choice is
// pbrt-v3's, uniform, so the weights are reflect/½ and transmit/½, not 1, and
// paths inside the sphere carry their variance: 5 standard errors, each under
// 1 %. The direct integrator sees the reflected part alone (the inside
// is dark to light samples): reflect · L.
TEST(RenderTranslucent, LosslessSphereInAWhiteFurnaceIsInvisible) {
  const double sky = 1.5, reflect[3] = {0.3, 0.5, 0.6};
  const std::string scene = R"json({
    "render": {"resolution": [24, 24], "integrator": "path", "max_depth": 200},
    "camera": {"position": ["0 m", "0 m", "4 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"},
    "materials": {"paper": {"type": "translucent", "diffuse": 1, "specular": 0, "reflect": [0.3, 0.5, 0.6],
                            "transmit": [0.7, 0.5, 0.4], "alpha": 0.3}},
    "shapes": [{"type": "sphere", "material": "paper", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
    "lights": [{"type": "environment", "radiance": "1.5 W/(m2 sr)"}]})json";
  for (IntegratorType integrator : {IntegratorType::path, IntegratorType::direct})
    for (const Knobs& knobs : estimator_knobs()) {
      auto adjust = [&](RenderSettings& s) {
        knobs.apply(s);
        s.integrator = integrator;
      };
      const Image on_sphere = render_text(scene, 512, 2, CropWindow{8, 8, 8, 8}, adjust);
      for (int c = 0; c < 3; ++c) {
        const double expected = integrator == IntegratorType::path ? sky : reflect[c] * sky;
        const Estimate e = channel_estimate(on_sphere, c);
        const char* name = integrator == IntegratorType::path ? "path" : "direct";
        EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 1e-6) << name << ", " << knobs.name << ", channel " << c;
        EXPECT_LT(e.standard_error, 0.01 * expected) << name << ", " << knobs.name << ", channel " << c;
      }
    }
}

// A 4 m translucent square at z = 0 (reflect 0, transmit 1), seen along its
// normal from z = 4 m through a 0.1° camera, lit only from behind by a
// distant light of irradiance E from `theta` off the normal. `facing_camera`:
// the square's normal (its outside, the interface's index-1 side) points at
// the camera.
Scene sheet_before_the_sun(const std::string& material, bool facing_camera, double irradiance, double theta) {
  const std::string edges = facing_camera ? R"("edge_u": ["4 m", "0 m", "0 m"], "edge_v": ["0 m", "4 m", "0 m"])"
                                          : R"("edge_u": ["0 m", "4 m", "0 m"], "edge_v": ["4 m", "0 m", "0 m"])";
  Scene scene = parse_scene(R"json({
    "render": {"resolution": [8, 8], "integrator": "path", "max_depth": 5, "photons": 1000},
    "camera": {"position": ["0 m", "0 m", "4 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "0.1 deg"},
    "materials": {"sheet": )json" + material + R"json(},
    "shapes": [{"type": "quad", "material": "sheet", "origin": ["-2 m", "-2 m", "0 m"], )json" + edges + "}]}",
                            "test.json", SAFEGI_SCENES_DIR);
  DistantLight sun;
  sun.direction = DirectionWorld(static_cast<Real>(std::sin(theta)), 0, static_cast<Real>(-std::cos(theta)));
  sun.irradiance = spectrum<dim::irradiance>(static_cast<Real>(irradiance) * units::watt_per_square_metre);
  scene.distant_lights.push_back(sun);
  return scene;
}

// Every pixel of `scene` under every integrator and knob is `expected` within
// `relative` (one delta light seen through the surface: nothing random is
// left but for float rounding and the camera's 0.1° spread).
void expect_every_pixel(Scene scene, double expected, double relative, const std::string& what) {
  for (IntegratorType integrator : {IntegratorType::direct, IntegratorType::path, IntegratorType::photon})
    for (const Knobs& knobs : estimator_knobs()) {
      scene.settings.integrator = integrator;
      const Image image = render_scene(scene, 4, 2, std::nullopt, knobs.apply);
      for (float v : image.rgb)
        ASSERT_NEAR(v, expected, relative * expected) << what << ", integrator " << static_cast<int>(integrator) << ", "
                                                      << knobs.name;
    }
}

// Lambert's transmission alone: L = Kd · transmit / π · E · cos θ, from either
// side (the diffuse lobes do not tell the interface's sides apart).
TEST(RenderTranslucent, DiffuseTransmissionOfADistantLight) {
  const double kd = 0.6, transmit = 0.9, irradiance = 2, theta = 50 * kPiD / 180;
  const std::string material =
      R"({"type": "translucent", "diffuse": 0.6, "specular": 0, "reflect": 0, "transmit": 0.9, "alpha": 0.3})";
  for (bool facing_camera : {true, false})
    expect_every_pixel(sheet_before_the_sun(material, facing_camera, irradiance, theta),
                       kd * transmit / kPiD * irradiance * std::cos(theta), 1e-5,
                       facing_camera ? "facing the camera" : "facing the light");
}

// Straight through (ωo = n, ωi = −n) the refracting facets are the normal's:
// h = n, ωo·h = 1, ωi·h = −1, G = 1, D(n) = 1/(π α²), so Walter's BTDF for
// radiance is (1 − F(1)) D(n) / (1 − η)², η = n_far / n_near, and
// L = transmit (Kd/π + Ks (1 − F₀) / (π α² (1 − η)²)) E with F₀ = 0.04. From
// outside η = 1.5, from inside 1/1.5: the glossy part 1.5² brighter, the
// radiance compressed into the denser side seen from within it. Within 2e-4:
// the 0.1° camera's spread tilts h by up to 0.013° there.
TEST(RenderTranslucent, GlossyTransmissionStraightThroughEitherSide) {
  const double kd = 0.6, ks = 0.3, alpha = 0.5, irradiance = 2, f0 = 0.04;
  const std::string material =
      R"({"type": "translucent", "diffuse": 0.6, "specular": 0.3, "reflect": 0, "transmit": 1, "alpha": 0.5})";
  for (bool facing_camera : {true, false}) {
    const double eta = facing_camera ? 1.5 : 1 / 1.5;
    const double glossy = ks * (1 - f0) / (kPiD * alpha * alpha * (1 - eta) * (1 - eta));
    expect_every_pixel(sheet_before_the_sun(material, facing_camera, irradiance, 0), (kd / kPiD + glossy) * irradiance,
                       2e-4, facing_camera ? "facing the camera" : "facing the light");
  }
}

// Rough glass (pbrt-v3's glass with roughness: translucent's glossy lobes on
// an interface of index `ior`) straight through, as above with Kd 0, Ks 1:
// L = Kt (1 − F₀) / (π α² (1 − η)²) E, F₀ = ((ior − 1)/(ior + 1))², η = ior
// from outside and 1/ior from inside. Reflection weighs by Kr, which light
// from behind never reaches. (The camera's 0.1° tilts h by up to 1/(1 − η)
// times its half-angle, so η near 1 and a sharp lobe would need a looser bound:
// at ior 1.33, α 0.4 the pixels fall 2.3e-4 below the centre's value.)
TEST(RenderTranslucent, RoughGlassStraightThroughEitherSide) {
  const double ior = 1.6, kt = 0.8, alpha = 0.5, irradiance = 2;
  const double f0 = (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1));
  const std::string material = R"({"type": "glass", "ior": 1.6, "reflectance": 0.5, "transmittance": 0.8, "alpha": 0.5})";
  for (bool facing_camera : {true, false}) {
    const double eta = facing_camera ? ior : 1 / ior;
    const double expected = kt * (1 - f0) / (kPiD * alpha * alpha * (1 - eta) * (1 - eta)) * irradiance;
    expect_every_pixel(sheet_before_the_sun(material, facing_camera, irradiance, 0), expected, 2e-4,
                       facing_camera ? "facing the camera" : "facing the light");
  }
}

// An emitting 2 m square 1 m behind the sheet (Kd 1, transmit 1), facing it:
// the sheet's centre receives E = π Le · 4 F, F the form factor of a 1 m ×
// 1 m rectangle from a point 1 m below its corner, (1/2π)(2 (1/√2)
// atan(1/√2)); the camera (0.5°) sees that centre: L = E / π. Light samples
// and transmitted BSDF samples both reach the emitter: under every knob, MIS
// on or off, and with the direct integrator too.
TEST(RenderTranslucent, AreaLightBehindTheSheetByBothStrategies) {
  const double emission = 3, form_factor = 4 * (1 / (2 * kPiD)) * 2 * (1 / std::sqrt(2.0)) * std::atan(1 / std::sqrt(2.0));
  const double expected = emission * form_factor;
  const std::string scene = R"json({
    "render": {"resolution": [8, 8], "integrator": "path", "max_depth": 5},
    "camera": {"position": ["0 m", "0 m", "4 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "0.5 deg"},
    "materials": {"sheet": {"type": "translucent", "diffuse": 1, "specular": 0, "reflect": 0, "transmit": 1, "alpha": 0.3}},
    "shapes": [
      {"type": "quad", "material": "sheet", "origin": ["-3 m", "-3 m", "0 m"], "edge_u": ["6 m", "0 m", "0 m"],
       "edge_v": ["0 m", "6 m", "0 m"]},
      {"type": "quad", "origin": ["-1 m", "-1 m", "-1 m"], "edge_u": ["2 m", "0 m", "0 m"], "edge_v": ["0 m", "2 m", "0 m"],
       "emission": "3 W/(m2 sr)"}]})json";
  for (IntegratorType integrator : {IntegratorType::path, IntegratorType::direct})
    for (const Knobs& knobs : estimator_knobs()) {
      auto adjust = [&](RenderSettings& s) {
        knobs.apply(s);
        s.integrator = integrator;
      };
      const Estimate e = channel_estimate(render_text(scene, 256, 2, std::nullopt, adjust), 1);
      EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 2e-4 * expected)
          << static_cast<int>(integrator) << ", " << knobs.name;
      EXPECT_LT(e.standard_error, 0.01 * expected) << static_cast<int>(integrator) << ", " << knobs.name;
    }
}

}  // namespace
}  // namespace safegi::render
