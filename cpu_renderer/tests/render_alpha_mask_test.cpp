// Alpha masks (pbrt-v3's "alpha" and "shadowalpha"): where a mask is 0 the
// surface is not there — for every ray (alpha) or for shadow rays only
// (shadow_alpha) — and rays go on to what lies beyond.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

#include "render_test_support.hpp"
#include "safegi/cpu_renderer/image.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// Seen from 5 m above, black quads at `heights` over an emitting floor
// (Le = 2): their mask is 0 on the texels left of `first_opaque` of 64
// (bilinear, clamped: exactly 0 for u < (first_opaque − 0.5)/64). Each quad
// fills the view (4 m wide, seen through 20°); its u runs along x, as the
// image's columns do, so with one quad the mask's edge is at
// x = -2 + 4 · 31.5/64 m on it, 2 d tan 10° / 32 m per pixel there
// (d = 5 m − height). Gives the image and that edge's column.
std::pair<Image, double> render_masked_quads_over_floor(const std::vector<double>& heights, int first_opaque = 32) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("safegi-alpha-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  Image mask{64, 1, std::vector<float>(3 * 64, 0.0f)};
  std::fill(mask.rgb.begin() + 3 * first_opaque, mask.rgb.end(), 1.0f);
  write_pfm(directory / "mask.pfm", mask);
  std::string quads;
  for (double height : heights)
    quads += R"json(, {"type": "quad", "origin": ["-2 m", ")json" + std::to_string(height) +
             R"json( m", "-2 m"], "edge_u": ["4 m", "0 m", "0 m"], "edge_v": ["0 m", "0 m", "4 m"],
                        "alpha": {"texture": "mask"}})json";
  const std::string scene = R"json({
    "render": {"resolution": [32, 32], "integrator": "path"},
    "camera": {"position": ["0 m", "5 m", "0 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 0, -1], "fov": "20 deg"},
    "textures": {"mask": {"type": "image", "file": "mask.pfm", "filter": "bilinear", "wrap": "clamp"}},
    "shapes": [{"type": "quad", "origin": ["-10 m", "0 m", "-10 m"], "edge_u": ["0 m", "0 m", "20 m"],
                "edge_v": ["20 m", "0 m", "0 m"], "emission": "2 W/(m2 sr)"})json" +
                           quads + "]}";
  Image image = render_text(scene, 16, 2, std::nullopt, {}, directory);
  std::filesystem::remove_all(directory);
  const double metres_per_pixel = 2 * (5 - heights.front()) * std::tan(10 * kPiD / 180) / 32;
  return {std::move(image), 16 + (-2 + 4 * 31.5 / 64) / metres_per_pixel};
}

// With the quad 1 m up, the floor shows where the mask is 0 at its full
// radiance and the quad's black elsewhere; pixels that straddle the edge lie between.
TEST(RenderAlphaMask, CameraRaysPassWhereTheMaskIsZero) {
  const auto [image, edge_column] = render_masked_quads_over_floor({1});
  int open = 0, closed = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const float value = image.pixel(x, y)[0];
      if (x + 1 < edge_column) {
        EXPECT_NEAR(value, 2.0f, 1e-5f) << x << ", " << y;
        ++open;
      } else if (x > edge_column) {
        EXPECT_EQ(value, 0.0f) << x << ", " << y;
        ++closed;
      } else {
        EXPECT_GE(value, 0.0f);
        EXPECT_LE(value, 2.0f + 1e-5f);
      }
    }
  EXPECT_GT(open, 400);
  EXPECT_GT(closed, 400);
}

// The masked quad in the emitting floor's plane (a box's bottom on a floor,
// as in pbrt-v3-rs's triangles-alpha-mask): through its holes the floor shows
// to every ray, as in pbrt-v3, whose mask test is part of the triangle's
// intersection; where the quad is there the two tie, and each is seen by
// about half the rays (a fair coin per ray), not by the hierarchy's order.
TEST(RenderAlphaMask, ASurfaceInTheMaskedPlaneShowsThroughItsHoles) {
  const auto [image, edge_column] = render_masked_quads_over_floor({0});
  int open = 0, closed = 0, closed_pixels_differing = 0;
  double closed_sum = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 1; x < 32; ++x) {
      const float value = image.pixel(x, y)[0];
      if (x + 1 < edge_column) {
        EXPECT_NEAR(value, 2.0f, 1e-5f) << x << ", " << y;
        ++open;
      } else if (x > edge_column) {
        closed_sum += value;
        closed_pixels_differing += std::abs(value - image.pixel(x - 1, y)[0]) > 1e-3f;
        ++closed;
      }
    }
  ASSERT_GT(open, 300);
  ASSERT_GT(closed, 300);
  // 16 coin flips a pixel: a mean of 1 (half of 2), its spread 0.5 / √(16 · closed).
  EXPECT_NEAR(closed_sum / closed, 1.0, 0.05);
  EXPECT_GT(closed_pixels_differing, closed / 2);  // noise, not one surface in blocks
}

// Forty quads masked everywhere, a centimetre apart, more than a ray skips
// from one origin (16) before it goes on from beyond the last: the floor
// shows in every pixel.
TEST(RenderAlphaMask, ARayPassesManyMaskedLayers) {
  std::vector<double> heights;
  for (int i = 1; i <= 40; ++i) heights.push_back(0.01 * i);
  const Image image = render_masked_quads_over_floor(heights, 64).first;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) EXPECT_NEAR(image.pixel(x, y)[0], 2.0f, 1e-5f) << x << ", " << y;
}

// A diffuse floor under a point light 3 m up, a 1 m occluder at 2 m between:
// its shadow spans |x|, |z| < 1.5 m on the floor, the camera 5 m up sees past
// it only where |x| or |z| > 0.83 m. In that ring the floor is dark under an
// opaque occluder and lit, L = ρ/π · I cos θ / r², when the occluder's
// shadow_alpha is 0 (it casts no shadow) or its alpha is (it is not there).
TEST(RenderAlphaMask, ShadowAlphaLetsLightThrough) {
  auto render_with = [](const std::string& occluder_mask) {
    const std::string scene = R"json({
      "render": {"resolution": [33, 33], "integrator": "direct"},
      "camera": {"position": ["0 m", "5 m", "0 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 0, -1], "fov": "40 deg"},
      "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [{"type": "quad", "material": "matte", "origin": ["-10 m", "0 m", "-10 m"],
                  "edge_u": ["0 m", "0 m", "20 m"], "edge_v": ["20 m", "0 m", "0 m"]},
                 {"type": "quad", "material": "matte", "origin": ["-0.5 m", "2 m", "-0.5 m"],
                  "edge_u": ["0 m", "0 m", "1 m"], "edge_v": ["1 m", "0 m", "0 m"])json" +
                             occluder_mask + R"json(}],
      "lights": [{"type": "point", "position": ["0 m", "3 m", "0 m"], "intensity": "10 W/sr"}]})json";
    return render_text(scene, 16);
  };
  const Image opaque = render_with(""), no_shadow = render_with(R"(, "shadow_alpha": 0)"),
              absent = render_with(R"(, "alpha": 0)");
  const double half = std::tan(20 * kPiD / 180), pixel = 2 * 5 * half / 33;
  int ring = 0;
  for (int py = 0; py < 33; ++py)
    for (int px = 0; px < 33; ++px) {
      const double x = 5 * (2 * (px + 0.5) / 33 - 1) * half, z = -5 * (1 - 2 * (py + 0.5) / 33) * half;
      const double outer = std::max(std::fabs(x), std::fabs(z));
      if (!(outer > 0.5 * 5 / 3 + pixel && outer < 1.5 - pixel)) continue;
      ++ring;
      const double expected = footprint_average(px, py, 33, half, 5, [](double fx, double fz) {
        const double r2 = fx * fx + fz * fz + 9;
        return 0.5 / kPiD * 10 * (3 / std::sqrt(r2)) / r2;
      });
      EXPECT_EQ(opaque.pixel(px, py)[0], 0.0f) << px << ", " << py;
      EXPECT_NEAR(no_shadow.pixel(px, py)[0], expected, 0.01 * expected) << px << ", " << py;
      EXPECT_NEAR(absent.pixel(px, py)[0], expected, 0.01 * expected) << px << ", " << py;
    }
  EXPECT_GT(ring, 20);
  // Straight down the middle the camera sees the occluder's top, 1 m under
  // the light, unless its alpha is 0: then the floor, 3 m under it.
  EXPECT_NEAR(no_shadow.pixel(16, 16)[0], 0.5 / kPiD * 10, 0.01 * 0.5 / kPiD * 10);
  EXPECT_NEAR(absent.pixel(16, 16)[0], 0.5 / kPiD * 10 / 9, 0.01 * 0.5 / kPiD * 10 / 9);
}

}  // namespace
}  // namespace safegi::render
