// Physics checks of whole renders against closed forms, with tolerances
// derived from the sample count (or, where the estimator is exact, from
// float rounding).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// Diffuse plane under a point light: L = ρ/π · I cos θ / r², averaged over
// each pixel's footprint on the plane (the estimator has no noise apart from
// where in the pixel the samples fall).
TEST(RenderPhysics, DiffusePlaneUnderPointLight) {
  const double rho = 0.5, intensity = 10.0, light_height = 2.0, camera_height = 5.0;
  const int size = 33;
  const double fov = 40.0;
  std::string scene = R"json({
    "render": {"resolution": [33, 33], "integrator": "direct"},
    "camera": {"position": {"value": [0, 5, 0], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 0, -1], "fov": "40 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}}],
    "lights": [{"type": "point", "position": {"value": [0, 2, 0], "unit": "m"}, "intensity": "10 W/sr"}]})json";
  for (const char* integrator : {"direct", "path"})
  for (const Knobs& knobs : estimator_knobs()) {
    std::string text = scene;
    text.replace(text.find("direct"), 6, integrator);
    Image image = render_text(text, 64, 2, std::nullopt, knobs.apply);
    const double half = std::tan(fov / 2 * kPiD / 180);
    double worst = 0;
    for (int py = 0; py < size; ++py) {
      for (int px = 0; px < size; ++px) {
        double expected = footprint_average(px, py, size, half, camera_height, [&](double x, double z) {
          double r2 = x * x + z * z + light_height * light_height;
          double cos_theta = light_height / std::sqrt(r2);
          return rho / kPiD * intensity * cos_theta / r2;
        });
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(image.pixel(px, py)[c] / expected - 1));
      }
    }
    // 64 stratified positions per pixel of a smooth function: well under 0.5%.
    EXPECT_LT(worst, 5e-3) << integrator << ", " << knobs.name;
  }
}

// A 20 m diffuse square at y = 0 of albedo `rho`, seen straight down from 5 m
// (17 × 17 pixels, 40°), lit by a distant light from `theta` off its normal.
Scene plane_under_the_sun(double rho, double irradiance, double theta) {
  Scene scene = parse_scene(R"json({
    "render": {"resolution": [17, 17], "integrator": "direct", "photons": 1000},
    "camera": {"position": {"value": [0, 5, 0], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 0, -1], "fov": "40 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 1}},
    "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}}]})json",
                            "test.json", SAFEGI_SCENES_DIR);
  std::get<LambertMaterial>(scene.materials[0].model).diffuse.value = Reflectance(static_cast<Real>(rho));
  DistantLight sun;
  sun.direction = DirectionWorld(static_cast<Real>(std::sin(theta)), static_cast<Real>(std::cos(theta)), 0);
  sun.irradiance = spectrum<dim::irradiance>(static_cast<Real>(irradiance) * units::watt_per_square_metre);
  scene.distant_lights.push_back(sun);
  return scene;
}

// Diffuse plane under a distant light (pbrt-v3's, from 50° off the normal):
// L = ρ/π · E cos θ everywhere, the estimator exact but for float rounding;
// with no specular surface the photon integrator traces its photons (from a
// disc across the scene) and gathers none, so it too is exact.
TEST(RenderPhysics, DiffusePlaneUnderDistantLight) {
  const double rho = 0.5, irradiance = 3.0, theta = 50 * kPiD / 180;
  Scene scene = plane_under_the_sun(rho, irradiance, theta);
  const double expected = rho / kPiD * irradiance * std::cos(theta);
  for (IntegratorType integrator : {IntegratorType::direct, IntegratorType::path, IntegratorType::photon})
    for (const Knobs& knobs : estimator_knobs()) {
      scene.settings.integrator = integrator;
      Image image = render_scene(scene, 4, 2, std::nullopt, knobs.apply);
      for (float v : image.rgb) ASSERT_NEAR(v, expected, 1e-5 * expected) << static_cast<int>(integrator) << ", " << knobs.name;
    }
}

// The same plane with pbrt-v3's bump map: a float image rising linearly along
// v (x) displaces the surface by `scale` per unit of its value, so the
// shading normal of a plane whose dp/dv is 20 m tilts away from the rise,
// towards −x, by atan(slope / 20 m), slope = scale · N/(N−1) per unit v (N
// rows, the texel centres 1/N apart and 1/(N−1) apart in value). The sun is
// 30° off the plane's normal towards +x: a tilt of 30° towards +x faces it
// (L = ρ/π · E), 20° towards −x turns away from it (ρ/π · E cos 50°). A sun
// 100° off the normal lights nothing, although a tilt of 60° would face it
// within 40°: light from below the real surface does not count.
Scene bumped_plane(double sun_theta, double tilt) {
  Scene scene = plane_under_the_sun(1, 3.0, sun_theta);
  const int rows = 64;
  Image ramp{1, rows, {}};
  for (int y = 0; y < rows; ++y) ramp.rgb.insert(ramp.rgb.end(), 3, static_cast<float>(y) / (rows - 1));
  ImageTexture texture;
  texture.name = "ramp";
  texture.mipmap = std::make_shared<MipMap>(std::move(ramp), TextureWrap::clamp);
  scene.textures.push_back(std::move(texture));
  const double slope = -20 * std::tan(tilt);  // metres of displacement per unit v; `tilt` towards +x
  scene.materials[0].bump = BumpMap{.texture = 0, .scale = static_cast<Real>(slope * (rows - 1) / rows) * units::meter};
  return scene;
}

TEST(RenderPhysics, BumpMapTiltsTheShadingNormal) {
  const double rho = 1, irradiance = 3.0, degree = kPiD / 180;
  struct Case {
    double sun, tilt, cosine;
  } cases[] = {{30 * degree, 30 * degree, 1}, {30 * degree, -20 * degree, std::cos(50 * degree)},
               {30 * degree, 0, std::cos(30 * degree)}, {100 * degree, 60 * degree, 0}};
  for (const Case& c : cases)
    for (IntegratorType integrator : {IntegratorType::direct, IntegratorType::path}) {
      Scene scene = bumped_plane(c.sun, c.tilt);
      scene.settings.integrator = integrator;
      const double expected = rho / kPiD * irradiance * c.cosine;
      Image image = render_scene(scene, 2);
      for (float v : image.rgb)
        ASSERT_NEAR(v, expected, 2e-4 * rho / kPiD * irradiance) << "sun " << c.sun / degree << "°, tilt " << c.tilt / degree << "°";
    }
}

// A procedural bump map: a float checkerboard of 1 m checks (values 0 and
// `step`) on the same plane. pbrt-v3's Bump takes forward differences 0.0005
// of u and v apart, 1 cm here (dp/du = dp/dv = 20 m): inside a check the
// normal is the plane's, and where a step into the next check lies within
// that 1 cm, the surface seems to rise by `step` over 1 cm, so the normal
// tilts by atan(step / 1 cm) — towards −x for a rise along +x (v). The sun
// straight above: L = ρ/π · E cos(tilt) there, ρ/π · E elsewhere.
TEST(RenderPhysics, ProceduralBumpMapTiltsAtTheChecksEdges) {
  const double irradiance = 3.0, step = 0.01;  // metres: a 45° tilt
  Scene scene = plane_under_the_sun(1, irradiance, 0);
  CheckerboardPattern board;
  board.mapping.u_scale = board.mapping.v_scale = 20;  // s = z + 10, t = x + 10
  board.even = Reflectance(Real(0));
  board.odd = Reflectance(Real(1));
  board.box_filtered = false;
  scene.patterns.push_back({"checks", board});
  scene.materials[0].bump = BumpMap{.pattern = 0, .scale = static_cast<Real>(step) * units::meter};
  const double flat = irradiance / kPiD;
  Image image = render_scene(scene, 64);
  int tilted = 0, level = 0;
  for (float v : image.rgb) {
    // A pixel is a mix of level points (flat) and points 1 cm before an edge along x or z (cos 45°, or
    // cos(atan √2) where both are): no value outside [cos(atan √2), 1] · flat, and both kinds are seen.
    ASSERT_GE(v, flat / std::sqrt(3.0) - 1e-4 * flat);
    ASSERT_LE(v, flat * (1 + 1e-4));
    level += v > flat * (1 - 1e-4);
    tilted += v < flat * 0.99;
  }
  EXPECT_GT(level, 0);
  EXPECT_GT(tilted, 0);
}

// The same plane with a box-filtered checkerboard of 1 m checks as its
// albedo: a pixel whose footprint, widened by a pixel on every side, lies in
// one check is that check's L = ρ/π · E cos θ exactly (but for rounding);
// the others, straddling an edge, lie between the two.
TEST(RenderPhysics, CheckerboardPlaneUnderDistantLight) {
  const double irradiance = 3.0, theta = 50 * kPiD / 180, even = 0.8, odd = 0.1;
  Scene scene = plane_under_the_sun(1, irradiance, theta);
  CheckerboardPattern board;
  board.mapping.u_scale = board.mapping.v_scale = 20;  // u runs along z, v along x: s = z + 10, t = x + 10
  board.even = Reflectance(static_cast<Real>(even));
  board.odd = Reflectance(static_cast<Real>(odd));
  scene.patterns.push_back({"checks", board});
  std::get<LambertMaterial>(scene.materials[0].model).diffuse.pattern = 0;
  const double per_albedo = irradiance * std::cos(theta) / kPiD;
  Image image = render_scene(scene, 16);
  const int size = 17;
  const double half = std::tan(20 * kPiD / 180), camera_height = 5;
  int whole[2] = {0, 0};
  for (int py = 0; py < size; ++py)
    for (int px = 0; px < size; ++px) {
      // The pixel's footprint on the plane, widened by a pixel: x = h·sx, z = -h·sy.
      auto x_at = [&](double pixel) { return camera_height * (2 * pixel / size - 1) * half; };
      auto z_at = [&](double pixel) { return -camera_height * (1 - 2 * pixel / size) * half; };
      const double x0 = x_at(px - 1), x1 = x_at(px + 2), z0 = z_at(py - 1), z1 = z_at(py + 2);
      const float value = image.pixel(px, py)[0];
      if (std::floor(x0) == std::floor(x1) && std::floor(z0) == std::floor(z1)) {
        const bool is_even = static_cast<long>(std::floor(x0) + std::floor(z0)) % 2 == 0;
        ++whole[is_even];
        EXPECT_NEAR(value, (is_even ? even : odd) * per_albedo, 1e-5) << px << ", " << py;
      } else {
        EXPECT_GE(value, odd * per_albedo * (1 - 1e-5)) << px << ", " << py;
        EXPECT_LE(value, even * per_albedo * (1 + 1e-5)) << px << ", " << py;
      }
    }
  EXPECT_GT(whole[0], 4);
  EXPECT_GT(whole[1], 4);
}

// Diffuse plane under a spot light pointing straight down: L = ρ/π · I f(θ)
// cos θ / r² with pbrt-v3's falloff f: 1 inside cone_angle − cone_delta,
// δ⁴ across the band (δ the cosine's position within it), 0 beyond. Averaged
// over each pixel's footprint; pixels wholly outside the cone are exactly 0.
TEST(RenderPhysics, DiffusePlaneUnderSpotLight) {
  const double rho = 0.5, intensity = 10.0, light_height = 2.0, camera_height = 5.0, fov = 60.0;
  const double cone = 30.0, delta = 10.0;
  const int size = 33;
  const double cos_total = std::cos(cone * kPiD / 180), cos_start = std::cos((cone - delta) * kPiD / 180);
  auto falloff = [&](double cos_theta) {
    if (cos_theta < cos_total) return 0.0;
    if (cos_theta >= cos_start) return 1.0;
    double d = (cos_theta - cos_total) / (cos_start - cos_total);
    return d * d * d * d;
  };
  std::string scene = R"json({
    "render": {"resolution": [33, 33], "integrator": "direct"},
    "camera": {"position": {"value": [0, 5, 0], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 0, -1], "fov": "60 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}}],
    "lights": [{"type": "spot", "position": {"value": [0, 2, 0], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
                "intensity": "10 W/sr", "cone_angle": "30 deg", "cone_delta": "10 deg"}]})json";
  // The same spot given by its power: I = P / (2π (1 − (cos start + cos total)/2)) sr.
  double power = intensity * 2 * kPiD * (1 - 0.5 * (cos_start + cos_total));
  std::string by_power = scene;
  by_power.replace(by_power.find("\"intensity\": \"10 W/sr\""), 22, "\"power\": \"" + std::to_string(power) + " W\"");
  for (const std::string* text : {&scene, &by_power})
  for (const char* integrator : {"direct", "path"}) {
    std::string variant = *text;
    variant.replace(variant.find("direct"), 6, integrator);
    Image image = render_text(variant, 64);
    const double half = std::tan(fov / 2 * kPiD / 180);
    const double peak = rho / kPiD * intensity / (light_height * light_height);
    double worst = 0;
    int dark = 0;
    for (int py = 0; py < size; ++py) {
      for (int px = 0; px < size; ++px) {
        double expected = footprint_average(px, py, size, half, camera_height, [&](double x, double z) {
          double r2 = x * x + z * z + light_height * light_height;
          double cos_theta = light_height / std::sqrt(r2);
          return rho / kPiD * intensity * falloff(cos_theta) * cos_theta / r2;
        });
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(image.pixel(px, py)[c] - expected) / peak);
        // A pixel whose footprint lies beyond the cone's edge (radius h·tan 30°, plus the pixel's diagonal) gets nothing.
        double cx = camera_height * (2 * (px + 0.5) / size - 1) * half, cz = camera_height * (1 - 2 * (py + 0.5) / size) * half;
        double pixel = 2 * camera_height * half / size;
        if (std::hypot(cx, cz) > light_height * std::tan(cone * kPiD / 180) + pixel) {
          ++dark;
          EXPECT_EQ(image.pixel(px, py)[0], 0.0f) << px << "," << py;
        }
      }
    }
    EXPECT_GT(dark, 100);
    // 64 stratified positions per pixel of a function with a kink at the
    // falloff's start: within 0.5% of the peak (a 1% brighter light fails).
    EXPECT_LT(worst, 5e-3) << integrator << (text == &scene ? ", intensity" : ", power");
  }
}

// White furnace: inside a closed sphere of albedo a emitting Le everywhere,
// L = Le / (1 - a) in every direction.
TEST(RenderPhysics, WhiteFurnace) {
  std::vector<Knobs> knobs = estimator_knobs();
  // Without roulette the path is cut at max_depth: 0.8^101 of L is missing.
  knobs.push_back({"roulette off", [](RenderSettings& s) { s.russian_roulette = false, s.max_depth = 100; }});
  for (const Knobs& knob : knobs)
  for (double albedo : {0.5, 0.8}) {
    std::string text = R"json({
      "render": {"resolution": [16, 16], "integrator": "path", "max_depth": 400},
      "camera": {"position": {"value": [0, 0, 0], "unit": "m"}, "look_at": {"value": [0, 0, -1], "unit": "m"},
                 "up": [0, 1, 0], "fov": "120 deg"},
      "materials": {"grey": {"type": "lambert", "reflectance": ALBEDO}},
      "shapes": [{"type": "sphere", "material": "grey", "center": {"value": [0.1, 0.2, 0], "unit": "m"}, "radius": "1 m",
                  "emission": "0.5 W/(m2 sr)", "two_sided": true}]})json";
    text.replace(text.find("ALBEDO"), 6, std::to_string(albedo));
    Image image = render_text(text, 64, 2, std::nullopt, knob.apply);
    double expected = 0.5 / (1 - albedo);
    for (int c = 0; c < 3; ++c) {
      Estimate estimate = channel_estimate(image, c);
      EXPECT_NEAR(estimate.mean, expected, 5 * estimate.standard_error + 1e-4 * expected)
          << "albedo " << albedo << ", " << knob.name;
      EXPECT_LT(estimate.standard_error, 0.01 * expected);  // the test has the power to see a 5% error
    }
  }
}

// Moving emitters: a closed box that turns, stretches and shifts while the
// shutter is open, and a sphere that grows and shifts, each around the camera.
// At every instant the enclosure is a white furnace, so L = Le / (1 - a); light
// samples taken where the emitter was at shutter open would miss it.
TEST(RenderPhysics, MovingEmittersAreSampledAtTheRayTime) {
  const std::string box = R"json({"type": "triangles", "material": "grey", "emission": "0.5 W/(m2 sr)", "two_sided": true,
      "positions": {"value": [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],
                    "unit": "m"},
      "indices": [0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5],
      "transform_at_close": [{"scale": [1.5, 1.2, 1.3]}, {"rotate": {"axis": [0.3, 1, 0.2], "angle": "40 deg"}},
                             {"translate": {"value": [0.2, 0.1, -0.1], "unit": "m"}}]})json";
  const std::string sphere = R"json({"type": "sphere", "material": "grey", "center": {"value": [0.1, 0.2, 0], "unit": "m"},
      "radius": "1 m", "emission": "0.5 W/(m2 sr)", "two_sided": true,
      "transform_at_close": [{"scale": 1.6}, {"translate": {"value": [0.3, 0, -0.2], "unit": "m"}}]})json";
  for (const std::string& shape : {box, sphere})
  for (const char* mis : {"true", "false"}) {
    std::string text = R"json({
      "render": {"resolution": [16, 16], "integrator": "path", "max_depth": 400, "mis": MIS},
      "camera": {"position": {"value": [0, 0, 0], "unit": "m"}, "look_at": {"value": [0, 0, -1], "unit": "m"},
                 "up": [0, 1, 0], "fov": "120 deg", "shutter": {"open": "0 s", "close": "10 ms"}},
      "materials": {"grey": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [SHAPE]})json";
    text.replace(text.find("MIS"), 3, mis);
    text.replace(text.find("SHAPE"), 5, shape);
    Image image = render_text(text, 64);
    const double expected = 0.5 / (1 - 0.5);
    Estimate estimate = channel_estimate(image, 0);
    EXPECT_NEAR(estimate.mean, expected, 5 * estimate.standard_error + 1e-4 * expected)
        << (shape == box ? "box" : "sphere") << ", mis " << mis;
    EXPECT_LT(estimate.standard_error, 0.01 * expected);
  }
}

// A sphere light (radius 0.1 m, Le 10 W/(m² sr)) whose centre is 1 m above a diffuse plane
// (ρ 0.5) at shutter open, seen at the point below it; `camera_extra` and `sphere_extra`
// add fields (a shutter, a transform_at_close). Direct lighting, 16², 64 spp: the estimate
// per knob of estimator_knobs(), checked against `expected` within `relative_error`.
void expect_sphere_light_above_plane(const std::string& camera_extra, const std::string& sphere_extra, double expected,
                                     double relative_error) {
  const std::string text = R"json({
    "render": {"resolution": [16, 16], "integrator": "direct"},
    "camera": {"position": {"value": [0, 0.5, 2], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 1, 0], "fov": "0.5 deg")json" + camera_extra + R"json(},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}},
               {"type": "sphere", "center": {"value": [0, 1, 0], "unit": "m"}, "radius": "0.1 m", "emission": "10 W/(m2 sr)")json" +
                           sphere_extra + "}]}";
  for (const Knobs& knobs : estimator_knobs()) {
    Image image = render_text(text, 64, 2, std::nullopt, knobs.apply);
    Estimate estimate = channel_estimate(image, 0);
    EXPECT_NEAR(estimate.mean, expected, 5 * estimate.standard_error + 2e-3 * expected) << knobs.name;
    EXPECT_LT(estimate.standard_error, relative_error * expected) << knobs.name << ": " << estimate.standard_error / expected;
  }
}

// Static: E = π Le (r/h)² exactly (the cone the sphere subtends, sin θmax = r/h), so
// L = ρ Le (r/h)². Sampled by that cone (as pbrt-v3 samples spheres), every shadow ray
// lands on the half that faces the point: the relative error is 4e-5, where area
// sampling gave 1.3e-3.
TEST(RenderPhysics, SphereLightAbovePlaneIsSampledByItsCone) {
  expect_sphere_light_above_plane("", "", 0.5 * 10.0 * 0.1 * 0.1 / (1.0 * 1.0), 1e-3);
}

// A sphere light of radius R rising from height d0 to d1 above a diffuse plane
// while the shutter is open: below it E = π Le (R/d)², and d moves linearly in
// time, so the time-averaged L = ρ Le R² / (d0 d1) — half what the shutter-open
// pose alone would give.
TEST(RenderPhysics, MovingSphereLightAbovePlane) {
  expect_sphere_light_above_plane(R"json(, "shutter": {"open": "0 s", "close": "20 ms"})json",
                                  R"json(, "transform_at_close": [{"translate": {"value": [0, 1, 0], "unit": "m"}}])json",
                                  0.5 * 10.0 * 0.1 * 0.1 / (1.0 * 2.0), 0.01);
}

// Irradiance from a parallel rectangle to a point below a corner, as a
// differential-area-to-rectangle form factor.
double corner_form_factor(double width, double length, double height) {
  double a = width / height, b = length / height;
  double sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
  return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2 * kPiD);
}

// A small square emitter above a diffuse plane: L = ρ · Le · F, with F the form
// factor from the point below its centre (four corner rectangles).
TEST(RenderPhysics, AreaLightAbovePlaneMatchesFormFactor) {
  std::string text = R"json({
    "render": {"resolution": [16, 16], "integrator": "direct"},
    "camera": {"position": {"value": [0, 0.5, 2], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 1, 0], "fov": "0.5 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}},
               {"type": "quad", "origin": {"value": [-0.1, 1, -0.1], "unit": "m"}, "edge_u": {"value": [0.2, 0, 0], "unit": "m"},
                "edge_v": {"value": [0, 0, 0.2], "unit": "m"}, "emission": "10 W/(m2 sr)"}]})json";
  double form_factor = 4 * corner_form_factor(0.1, 0.1, 1.0);
  double expected = 0.5 * 10.0 * form_factor;
  for (const char* integrator : {"direct", "path"})
  for (const Knobs& knobs : estimator_knobs()) {
    std::string scene = text;
    scene.replace(scene.find("direct"), 6, integrator);
    Image image = render_text(scene, 64, 2, std::nullopt, knobs.apply);
    Estimate estimate = channel_estimate(image, 0);
    // Path tracing finds nothing more: the emitter reflects no light.
    EXPECT_NEAR(estimate.mean, expected, 5 * estimate.standard_error + 1e-3 * expected) << integrator << ", " << knobs.name;
    EXPECT_LT(estimate.standard_error, 0.01 * expected) << integrator << ", " << knobs.name;
  }
}

// A mirror of reflectance r seen against a large emitter: L = r · Le exactly.
TEST(RenderPhysics, MirrorReflectsEmitter) {
  std::string text = R"json({
    "render": {"resolution": [24, 24], "integrator": "path"},
    "camera": {"position": {"value": [0, 1, 3], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 1, 0], "fov": "10 deg"},
    "materials": {"mirror": {"type": "mirror", "reflectance": [0.8, 0.5, 0.25]}},
    "shapes": [{"type": "quad", "material": "mirror", "origin": {"value": [-10, 0, -10], "unit": "m"},
                "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}},
               {"type": "quad", "origin": {"value": [-10, 2, -10], "unit": "m"}, "edge_u": {"value": [20, 0, 0], "unit": "m"},
                "edge_v": {"value": [0, 0, 20], "unit": "m"}, "emission": {"value": [3, 2, 1], "unit": "W/(m2 sr)"}}]})json";
  for (const char* integrator : {"path", "direct"}) {
    std::string scene = text;
    scene.replace(scene.find("\"path\""), 6, std::string("\"") + integrator + "\"");
    Image image = render_text(scene, 4);
    const float expected[3] = {0.8f * 3, 0.5f * 2, 0.25f * 1};
    for (int p = 0; p < image.width * image.height; ++p)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.rgb[3 * p + c], expected[c], 1e-5f * expected[c]) << integrator;
  }
}

// The Cornell box written in millimetres and in kilometres: radiance does not
// depend on scale, so the images must agree; acne at either scale would not.
TEST(RenderPhysics, SameImageInMillimetresAndKilometres) {
  std::string metres = read_text(std::filesystem::path(SAFEGI_SCENES_DIR) / "cornell-box/cornell-box.json");
  auto in_unit = [&](const std::string& unit) {
    std::string text = metres;
    for (size_t at = text.find("\"unit\": \"m\""); at != std::string::npos; at = text.find("\"unit\": \"m\"", at + 1))
      text.replace(at, 11, "\"unit\": \"" + unit + "\"");
    // Meshes resolve against the scenes directory; point them into the box's folder.
    for (const char* mesh : {"short-box.obj", "tall-box.obj"}) {
      size_t at = text.find(mesh);
      text.replace(at, std::strlen(mesh), std::string("cornell-box/") + mesh);
    }
    return text;
  };
  std::string millimetres = in_unit("mm"), kilometres = in_unit("km");
  ASSERT_NE(millimetres.find("\"unit\": \"mm\""), std::string::npos);
  CropWindow window{0, 0, 32, 32};
  auto small = [](std::string text) {
    text.replace(text.find("[512, 512]"), 10, "[32, 32]");
    return text;
  };
  Image a = render_text(small(millimetres), 16, 2, window);
  Image b = render_text(small(kilometres), 16, 2, window);
  double difference = 0, total = 0;
  int outliers = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    difference += std::fabs(a.rgb[i] - b.rgb[i]);
    total += b.rgb[i];
    if (std::fabs(a.rgb[i] - b.rgb[i]) > 0.02 * std::max(b.rgb[i], 0.01f)) ++outliers;
  }
  EXPECT_LT(difference / total, 2e-3);
  EXPECT_LE(outliers, static_cast<int>(a.rgb.size() / 50));
  EXPECT_NEAR(channel_estimate(a, 0).mean, 0.19, 0.03);  // lit, not black from self-intersection
}

TEST(RenderDeterminism, ThreadCountDoesNotChangeTheImage) {
  for (const char* file : {"cornell-box/cornell-box.json", "moving-light.json"})
  for (const Knobs& knobs : estimator_knobs()) {
    Scene scene = load_scene(std::filesystem::path(SAFEGI_SCENES_DIR) / file);
    RenderOptions options;
    options.settings = scene.settings;
    options.settings.width = options.settings.height = 24;
    options.settings.spp = 8;
    knobs.apply(options.settings);
    std::vector<Image> images;
    for (int threads : {1, 2, 3}) {
      options.threads = threads;
      images.push_back(render(scene, options));
    }
    for (const Image& image : images) {
      ASSERT_EQ(image.rgb.size(), images[0].rgb.size());
      EXPECT_EQ(std::memcmp(image.rgb.data(), images[0].rgb.data(), image.rgb.size() * sizeof(float)), 0)
          << file << ", " << knobs.name;
    }
  }
}

// The crop, and with a pixel filter also any thread count (each sample stays
// in its own pixel, its offset drawn from the filter: pixel_filter.hpp).
TEST(RenderDeterminism, CropIsTheSameWindowOfTheFullImage) {
  Scene scene = load_scene(std::filesystem::path(SAFEGI_SCENES_DIR) / "cornell-box/cornell-box.json");
  PixelFilter mitchell;
  mitchell.type = PixelFilterType::mitchell;
  mitchell.radius_x = mitchell.radius_y = 2;
  for (const PixelFilter& filter : {PixelFilter{}, mitchell}) {
    const char* name = kPixelFilterNames[static_cast<int>(filter.type)];
    RenderOptions options;
    options.settings = scene.settings;
    options.settings.width = options.settings.height = 40;
    options.settings.spp = 4;
    options.settings.filter = filter;
    options.threads = 1;
    Image full = render(scene, options);
    for (int threads : {2, 3}) {
      options.threads = threads;
      Image many = render(scene, options);
      EXPECT_EQ(std::memcmp(full.rgb.data(), many.rgb.data(), full.rgb.size() * sizeof(float)), 0)
          << name << ", " << threads << " threads";
    }
    options.crop = CropWindow{13, 7, 17, 21};
    Image crop = render(scene, options);
    ASSERT_EQ(crop.width, 17);
    ASSERT_EQ(crop.height, 21);
    for (int y = 0; y < crop.height; ++y)
      EXPECT_EQ(std::memcmp(crop.pixel(0, y), full.pixel(13, 7 + y), 3 * sizeof(float) * crop.width), 0) << name;
  }
}

TEST(RenderDeterminism, SeedChangesTheNoiseOnly) {
  Scene scene = load_scene(std::filesystem::path(SAFEGI_SCENES_DIR) / "cornell-box/cornell-box.json");
  RenderOptions options;
  options.settings = scene.settings;
  options.settings.width = options.settings.height = 24;
  options.settings.spp = 8;
  Image a = render(scene, options);
  options.seed = 12345;
  Image b = render(scene, options);
  EXPECT_NE(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0);
  EXPECT_NEAR(channel_estimate(a, 0).mean, channel_estimate(b, 0).mean, 0.02);
}

}  // namespace
}  // namespace safegi::render
