// Interpolated vertex normals (pbrt-v3's "N") against analytic answers: a
// matte quad under a distant light, seen from straight above, reflects
// ρ/π · E · cos θ with θ the light's angle to the *shading* normal. With one
// tilted N at every vertex, that is the tilt's cosine everywhere (the geometric
// normal gives another); with N tilted by ±x at x = ±1, the interpolated normal
// at x is (sin t · x, 0, cos t) normalised — affine in x across both triangles —
// so the image is mirror-symmetric and its middle column is lit as head-on.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "render_test_support.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

constexpr double kAlbedo = 0.5, kIrradiance = 2.0;
constexpr int kSize = 9;

std::string vec(double x, double y, double z) {
  return std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z);
}

// The 2 m quad at z = 0 under a sun from `from`, seen from 1 m above; `normals`: the "N" of its four
// corners (-1,-1), (1,-1), (1,1), (-1,1), or none.
Scene quad_scene(const std::string& from, const std::string& normals,
                 const std::string& material = "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]") {
  const std::string text =
      "LookAt 0 0 1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20\n"
      "Film \"image\" \"integer xresolution\" " + std::to_string(kSize) + " \"integer yresolution\" " + std::to_string(kSize) +
      "\nIntegrator \"path\" \"integer maxdepth\" 1\nWorldBegin\n"
      "LightSource \"distant\" \"point from\" [" + from + "] \"point to\" [0 0 0] \"rgb L\" [2 2 2]\n" +
      material + "\n"
      "Shape \"trianglemesh\" \"point P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] \"integer indices\" [0 1 2 0 2 3]" +
      (normals.empty() ? std::string() : " \"normal N\" [" + normals + "]") + "\nWorldEnd\n";
  PbrtImportOptions options;
  options.metres_per_unit = 1;
  PbrtScene scene = parse_pbrt_scene(text, "quad.pbrt", ".", options);
  EXPECT_EQ(scene.warnings, "");
  return std::move(scene.scene);
}

double lit(double cosine) { return kAlbedo / kPiD * kIrradiance * cosine; }

void expect_uniform(const Image& image, double expected, const std::string& what) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.pixel(x, y)[c], expected, 1e-4 * expected) << what << " at " << x << ", " << y;
}

TEST(RenderShadingNormals, ATiltedNormalIsLitByItsOwnCosine) {
  const double tilt = 40 * kPiD / 180, sun = 30 * kPiD / 180;
  const std::string from = vec(std::sin(sun), 0, std::cos(sun));
  const std::string tilted = vec(std::sin(tilt), 0, std::cos(tilt));
  const Scene flat = quad_scene(from, "");
  const Scene smooth = quad_scene(from, tilted + " " + tilted + " " + tilted + " " + tilted);
  for (const Knobs& knobs : estimator_knobs()) {
    expect_uniform(render_scene(flat, 4, 2, std::nullopt, knobs.apply), lit(std::cos(sun)), std::string("no N, ") + knobs.name);
    expect_uniform(render_scene(smooth, 4, 2, std::nullopt, knobs.apply), lit(std::cos(tilt - sun)), std::string("tilted N, ") + knobs.name);
  }
}

// The sun above the surface but 100 degrees from the tilted normal: pbrt-v3's
// rule (the geometric normal says reflection, the Lambertian lobe has no
// hemisphere of its own) lights it by the cosine's magnitude, as pbrt-v3 does.
TEST(RenderShadingNormals, ASunBelowTheTiltedNormalButAboveTheSurfaceStillLightsIt) {
  const double tilt = 40 * kPiD / 180, sun = 60 * kPiD / 180;
  const std::string tilted = vec(std::sin(tilt), 0, std::cos(tilt));
  const Scene smooth = quad_scene(vec(-std::sin(sun), 0, std::cos(sun)), tilted + " " + tilted + " " + tilted + " " + tilted);
  for (const Knobs& knobs : estimator_knobs())
    expect_uniform(render_scene(smooth, 4, 2, std::nullopt, knobs.apply), lit(std::abs(std::cos(tilt + sun))), knobs.name);
}

// A translucent quad that only transmits (Kd 0.5, transmit 1), the sun below
// it: lit through the surface by the cosine to its shading normal, where
// that puts the sun below as well. Where the tilted normal puts the sun above
// (the geometric normal still below), it counts nothing: a transmitting BSDF
// keeps to the shading normal's sides (pbrt-v3's LambertianTransmission, with
// no hemisphere of its own, would count it; reflection follows pbrt-v3, above).
// Nor does a sun above the surface that the tilted normal puts below: the
// geometric normal says reflection, which this material has none of.
TEST(RenderShadingNormals, ATiltedNormalTransmitsByItsOwnCosine) {
  const std::string paper = "Material \"translucent\" \"rgb Kd\" [0.5 0.5 0.5] \"rgb Ks\" [0 0 0] \"rgb reflect\" [0 0 0] "
                            "\"rgb transmit\" [1 1 1]";
  const double tilt = 40 * kPiD / 180, d30 = 30 * kPiD / 180, d60 = 60 * kPiD / 180;
  const std::string tilted = vec(std::sin(tilt), 0, std::cos(tilt));
  const std::string normals = tilted + " " + tilted + " " + tilted + " " + tilted;
  struct Sun {
    const char* where;
    std::string from;
    double flat, smooth;
  };
  const Sun suns[] = {{"below, 30 deg", vec(std::sin(d30), 0, -std::cos(d30)), lit(std::cos(d30)), lit(std::cos(d30 + tilt))},
                      {"below, 60 deg", vec(std::sin(d60), 0, -std::cos(d60)), lit(std::cos(d60)), 0},
                      {"above, -60 deg", vec(-std::sin(d60), 0, std::cos(d60)), 0, 0}};
  for (const Sun& sun : suns) {
    const Scene flat = quad_scene(sun.from, "", paper), smooth = quad_scene(sun.from, normals, paper);
    for (const Knobs& knobs : estimator_knobs()) {
      const std::string what = std::string(sun.where) + ", " + knobs.name;
      for (const auto& [scene, expected, name] : {std::tuple{&flat, sun.flat, "no N, "}, std::tuple{&smooth, sun.smooth, "tilted N, "}}) {
        const Image image = render_scene(*scene, 4, 2, std::nullopt, knobs.apply);
        if (expected > 0) expect_uniform(image, expected, name + what);
        if (expected == 0) {
          for (float v : image.rgb) ASSERT_EQ(v, 0.0f) << name << what;
        }
      }
    }
  }
}

// N equal to the geometric normal changes nothing.
TEST(RenderShadingNormals, TheGeometricNormalAsNIsTheFlatImage) {
  const std::string from = vec(0.3, 0.2, 0.9), up = vec(0, 0, 1);
  const Image flat = render_scene(quad_scene(from, ""), 4, 2);
  const Image smooth = render_scene(quad_scene(from, up + " " + up + " " + up + " " + up), 4, 2);
  for (size_t i = 0; i < flat.rgb.size(); ++i) ASSERT_NEAR(smooth.rgb[i], flat.rgb[i], 1e-6 * flat.rgb[i]) << i;
}

TEST(RenderShadingNormals, NormalsAreInterpolatedAcrossTheTriangles) {
  const double tilt = 40 * kPiD / 180, s = std::sin(tilt), c = std::cos(tilt);
  const std::string left = vec(-s, 0, c), right = vec(s, 0, c);
  const Image image = render_scene(quad_scene(vec(0, 0, 1), left + " " + right + " " + right + " " + left), 64, 2);
  const int middle = kSize / 2;
  // Half a pixel either side of the middle, the normal turns by under 0.6°: the cosine is 1 within 1e-4.
  for (int y = 0; y < kSize; ++y) {
    EXPECT_NEAR(image.pixel(middle, y)[0], lit(1.0), 2e-4 * lit(1.0)) << "row " << y;
    for (int x = 0; x < middle; ++x) {
      EXPECT_NEAR(image.pixel(x, y)[0], image.pixel(kSize - 1 - x, y)[0], 2e-4 * lit(1.0)) << x << ", " << y;
      EXPECT_LT(image.pixel(x, y)[0], image.pixel(x + 1, y)[0]) << "darker away from the middle: " << x << ", " << y;
    }
  }
  // The outermost column, centred at x = 4·(2 tan 10°)/9 from the middle: cos = c / |(s x, 0, c)|, within the
  // curvature of the cosine across its pixel.
  const double x = 4 * 2 * std::tan(10 * kPiD / 180) / kSize;
  EXPECT_NEAR(image.pixel(kSize - 1, middle)[0], lit(c / std::hypot(s * x, c)), 2e-3 * lit(1.0));
}

}  // namespace
}  // namespace safegi::render
