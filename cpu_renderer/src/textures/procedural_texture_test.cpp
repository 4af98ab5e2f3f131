// The procedural patterns against their definitions: noise's lattice zeros
// and bounds, the octave counts a footprint leaves, the checkerboard's
// closed-form box filter against a brute-force average of point samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "textures/noise.hpp"
#include "safegi/cpu_renderer/procedural_texture.hpp"

namespace safegi::render {
namespace {

Real channel(Reflectance value, int c) { return sg::raw(value)[c]; }
Reflectance grey(Real v) { return sg::from_raw<Reflectance>(sg::vec3_rep(v)); }

TEST(Noise, VanishesOnTheLatticeAndStaysNearTheUnitInterval) {
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) EXPECT_EQ(perlin_noise(NoisePoint{Real(x), Real(y), 7}), 0) << x << ", " << y;
  Real lowest = 0, highest = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      for (int k = 0; k < 40; ++k) {
        Real n = perlin_noise(NoisePoint{i * Real(0.173), j * Real(0.231) - 3, k * Real(0.197) + 11});
        lowest = std::min(lowest, n);
        highest = std::max(highest, n);
      }
  EXPECT_LT(lowest, -0.5f);  // it takes both signs, to about ±1
  EXPECT_GT(highest, 0.5f);
  EXPECT_GE(lowest, -1.1f);
  EXPECT_LE(highest, 1.1f);
  // Periodic in 256; the 2D noise is the plane z = 0.5; not-finite input is 0.
  EXPECT_NEAR(perlin_noise(NoisePoint{Real(1.3), Real(2.7), Real(0.4)}),
              perlin_noise(NoisePoint{Real(257.3), Real(-253.3), Real(512.4)}), 1e-4);
  EXPECT_EQ(perlin_noise(Real(1.3), Real(2.7)), perlin_noise(NoisePoint{Real(1.3), Real(2.7), Real(0.5)}));
  EXPECT_EQ(perlin_noise(NoisePoint{std::nanf(""), 0, 0}), 0);
  EXPECT_EQ(perlin_noise(NoisePoint{Real(1e30), Real(0.5), Real(0.5)}), perlin_noise(NoisePoint{Real(1e30), Real(0.5), Real(0.5)}));
}

// pbrt-v3 keeps n = -1 - log2(footprint) octaves (clamped to the maximum):
// a zero footprint keeps all, one of 1/2 or more none.
TEST(Noise, FootprintsDropTheOctavesFinerThanThem) {
  const NoisePoint p{Real(0.37), Real(1.91), Real(-2.3)};
  Real all = 0, amplitude = 1, frequency = 1;
  for (int i = 0; i < 5; ++i, amplitude *= 0.5f, frequency *= 1.99f)
    all += amplitude * perlin_noise(NoisePoint{p.x * frequency, p.y * frequency, p.z * frequency});
  EXPECT_NEAR(fbm(p, 0, 0.5f, 5), all, 1e-5);
  EXPECT_EQ(fbm(p, 0.5f, 0.5f, 5), 0);
  EXPECT_EQ(fbm(p, 4, 0.5f, 5), 0);
  // Turbulence counts each dropped octave as 0.2 of its amplitude, and the
  // partial octave after the kept ones as 0.2 more where its fade is 0 (as
  // pbrt-v3 sums them: the first dropped amplitude is counted twice).
  EXPECT_NEAR(turbulence(p, 1, 0.5f, 4), 0.2f + 0.2f * (1 + 0.5f + 0.25f + 0.125f), 1e-6);
  EXPECT_NEAR(turbulence(p, 0, 0.5f, 3), std::abs(perlin_noise(p)) + 0.5f * std::abs(perlin_noise(NoisePoint{p.x * 1.99f, p.y * 1.99f, p.z * 1.99f})) +
                                            0.25f * std::abs(perlin_noise(NoisePoint{p.x * 1.99f * 1.99f, p.y * 1.99f * 1.99f, p.z * 1.99f * 1.99f})) +
                                            0.125f * 0.2f,
              1e-5);
}

CheckerboardPattern board(bool box_filtered) {
  return CheckerboardPattern{Mapping2D{}, grey(0.8f), grey(0.1f), box_filtered};
}

// pbrt-v3's TextureMapping2D formulas (texture.cpp), at points whose answers are known: a texture space
// that is the render world itself, in metres.
TEST(ProceduralTexture, MappingsAsPbrtV3MapsPoints) {
  auto at = [](const Mapping2D& m, float x, float y, float z) {
    return m.at(0.3f, 0.7f, sg::from_raw<PointWorld>(sg::vec3_rep(x, y, z)));
  };
  auto expect_st = [](TextureCoordinates st, float s, float t, const char* what) {
    EXPECT_NEAR(st.s, s, 1e-6f) << what;
    EXPECT_NEAR(st.t, t, 1e-6f) << what;
  };
  Mapping2D uv;
  uv.u_scale = 2;
  uv.v_offset = 0.5f;
  expect_st(at(uv, 9, 9, 9), 0.6f, 1.2f, "uv: (u·2, v + 0.5), whatever the point");
  Mapping2D sphere;
  sphere.kind = Mapping2D::Kind::spherical;
  expect_st(at(sphere, 0, 0, 2), 0, 0, "spherical: the +z pole");
  expect_st(at(sphere, 0, 3, 0), 0.5f, 0.25f, "spherical: θ = π/2, φ = π/2");
  expect_st(at(sphere, -1, -1, 0), 0.5f, 0.625f, "spherical: φ = 5π/4, past 2π's wrap");
  Mapping2D cylinder;
  cylinder.kind = Mapping2D::Kind::cylindrical;
  expect_st(at(cylinder, 0, 2, 1), 0.75f, 1 / std::sqrt(5.0f), "cylindrical: (π + π/2)/2π, d.z");
  Mapping2D plane;
  plane.kind = Mapping2D::Kind::planar;
  plane.t_axis = sg::vec3_rep(0, 0, 1);
  plane.u_offset = 0.5f;
  expect_st(at(plane, 2, 3, 4), 2.5f, 4, "planar: udelta + p·v1, vdelta + p·v2");
  EXPECT_EQ(plane.uv_scale(), 0.0f);  // not following (u, v): unfiltered
  EXPECT_EQ(uv.uv_scale(), 2.0f);
}

TEST(ProceduralTexture, CheckerboardCellsAlternateOnBothSidesOfZero) {
  const Pattern pattern = board(false);
  auto at = [&](Real u, Real v) { return channel(evaluate(pattern, PatternLookup{.u = u, .v = v}), 0); };
  EXPECT_EQ(at(0.5f, 0.5f), 0.8f);
  EXPECT_EQ(at(1.5f, 0.5f), 0.1f);
  EXPECT_EQ(at(-0.5f, 0.5f), 0.1f);  // ⌊-0.5⌋ + 0 = -1: odd
  EXPECT_EQ(at(-0.5f, -0.5f), 0.8f);
  EXPECT_EQ(at(1e9f, 0.5f), 0.8f);  // far out, no int overflow
}

// The closed form is the box filter's exact average: compare it with a
// 400 × 400 midpoint average of point samples over the same box, as wide in
// u and in v as the lookup says (a footprint stretched along one of them too).
TEST(ProceduralTexture, CheckerboardBoxFilterIsTheAverageOverTheFootprint) {
  const Pattern filtered = board(true), point = board(false);
  const Real cases[][4] = {{0.5f, 0.5f, 0.2f, 0.2f}, {0.9f, 0.3f, 0.25f, 0.25f}, {1.1f, 0.95f, 0.3f, 0.05f},
                           {-0.2f, 2.05f, 0.1f, 0.7f}, {3.3f, -1.6f, 2.5f, 2.5f}};
  for (const auto& c : cases) {
    const Real u = c[0], v = c[1], width_u = c[2], width_v = c[3];
    double sum = 0;
    constexpr int n = 400;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Real du = (2 * (i + 0.5f) / n - 1) * width_u, dv = (2 * (j + 0.5f) / n - 1) * width_v;
        sum += channel(evaluate(point, PatternLookup{.u = u + du, .v = v + dv}), 0);
      }
    const Real closed =
        channel(evaluate(filtered, PatternLookup{.u = u, .v = v, .u_footprint = width_u, .v_footprint = width_v}), 0);
    EXPECT_NEAR(closed, sum / (n * n), 4e-3) << u << ", " << v << ", " << width_u << " × " << width_v;
  }
}

TEST(ProceduralTexture, BoundsAndMeans) {
  const Pattern checks = board(true);
  EXPECT_NEAR(channel(mean_value(checks), 0), 0.45f, 1e-6);
  EXPECT_EQ(channel(largest_value(checks), 0), 0.8f);
  // Dots cover about half the cells, each a disc of radius 0.35: π·0.35²/2 ≈ 0.19.
  const Pattern dots = DotsPattern{Mapping2D{}, grey(1), grey(0)};
  EXPECT_NEAR(channel(mean_value(dots), 0), 0.19f, 0.06f);
  // Noise sums are clamped below 0 only, as pbrt-v3 clamps a reflectance;
  // fbm takes both signs, so both ends occur.
  const Pattern cloud = FbmPattern{};
  const Real cloud_largest = channel(largest_value(cloud), 0);
  EXPECT_GT(cloud_largest, 0.5f);
  const Real mean = channel(mean_value(cloud), 0);
  EXPECT_GT(mean, 0.05f);
  EXPECT_LT(mean, 0.5f);
  int negative = 0;
  for (int i = 0; i < 100; ++i) {
    const PatternLookup at{.position = sg::from_raw<PointWorld>(sg::vec3_rep(0.13f * i, 0.71f * i, 0.29f * i))};
    const Real raw = channel(evaluate_unclamped(cloud, at), 0);
    EXPECT_EQ(channel(evaluate(cloud, at), 0), std::max(raw, Real(0)));
    negative += raw < 0;
  }
  EXPECT_GT(negative, 10);
}

// pbrt-v3's MarbleTexture::Evaluate transcribed: its segment is
// min(1, ⌊6t⌋), so from t = 1/6 on it extrapolates the second segment's cubic
// (to 1.5 · 27.08 = 40.6 in red at t = 1), and Spectrum::Clamp() takes
// negative values to 0. With variation 0 the phase is the point's y.
TEST(ProceduralTexture, MarbleIsPbrtV3sExtrapolatedSpline) {
  static const float c[9][3] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f}, {.5f, .5f, .5f}, {.6f, .59f, .58f},
                                {.58f, .58f, .6f}, {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};
  auto pbrt_v3 = [](float t, int channel_index) {
    const int nseg = 6, first = std::min(1, int(std::floor(t * nseg)));
    t = t * nseg - first;
    float p[4];
    for (int k = 0; k < 4; ++k) p[k] = c[first + k][channel_index];
    const float s0 = (1 - t) * ((1 - t) * ((1 - t) * p[0] + t * p[1]) + t * ((1 - t) * p[1] + t * p[2])) +
                     t * ((1 - t) * ((1 - t) * p[1] + t * p[2]) + t * ((1 - t) * p[2] + t * p[3]));
    return std::max(1.5f * s0, 0.0f);
  };
  MarblePattern marble;
  marble.variation = 0;
  Real brightest = 0;
  for (int i = 0; i <= 64; ++i) {
    const float y = -std::numbers::pi_v<float> / 2 + std::numbers::pi_v<float> * i / 64;  // t from 0 to 1
    const float t = 0.5f + 0.5f * std::sin(y);
    const Reflectance value = evaluate(marble, PatternLookup{.position = sg::from_raw<PointWorld>(sg::vec3_rep(0.3f, y, 0.7f))});
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(channel(value, ch), pbrt_v3(t, ch), 2e-4f * (1 + pbrt_v3(t, ch))) << t << ", " << ch;
    brightest = std::max(brightest, channel(value, 0));
  }
  EXPECT_NEAR(brightest, 40.62f, 0.01f);  // t = 1
  EXPECT_GE(channel(largest_value(marble), 0), Real(30));
}

TEST(ProceduralTexture, SolidPatternsReadTheTextureSpaceInItsUnit) {
  // Texture space is render space scaled by 1/2, in centimetres: cells of 2 cm.
  SolidCheckerboardPattern cubes{SolidMapping{}, grey(0.8f), grey(0.1f)};
  const glm::mat4 half(glm::mat3(0.5f));
  cubes.mapping.texture_from_render = sg::from_raw<TextureFromRender>(sg::matrix_pair{sg::mat4_rep(half), sg::mat4_rep(glm::inverse(half))});
  cubes.mapping.unit = 0.01f * units::metre;
  auto at = [&](float x) {
    return channel(evaluate(cubes, PatternLookup{.position = sg::from_raw<PointWorld>(sg::vec3_rep(x, 0.005f, 0.005f))}), 0);
  };
  EXPECT_EQ(at(0.01f), 0.8f);   // 0.5 units
  EXPECT_EQ(at(0.03f), 0.1f);   // 1.5 units
  EXPECT_EQ(at(-0.01f), 0.1f);  // -0.5 units
}

// pbrt-v3's UVTexture and BilerpTexture at chosen (s, t), uscale 2 doubling s.
TEST(ProceduralTexture, UvAndBilerpAsPbrtV3DefinesThem) {
  Mapping2D doubled;
  doubled.u_scale = 2;
  const Pattern uv = UvPattern{doubled};
  EXPECT_TRUE(reads_uv(uv));
  const Reflectance at = evaluate(uv, PatternLookup{.u = 0.7f, .v = -0.25f});
  EXPECT_NEAR(channel(at, 0), 0.4f, 1e-6);  // 1.4 − 1
  EXPECT_NEAR(channel(at, 1), 0.75f, 1e-6);  // −0.25 + 1
  EXPECT_EQ(channel(at, 2), 0);
  const Pattern corners =
      BilerpPattern{Mapping2D{}, grey(0.1f), grey(0.2f), grey(0.3f), sg::from_raw<Reflectance>(sg::vec3_rep(0.4f, 0.5f, 0.6f))};
  auto bilerp = [&](Real u, Real v, int c) { return channel(evaluate(corners, PatternLookup{.u = u, .v = v}), c); };
  EXPECT_NEAR(bilerp(0, 0, 0), 0.1f, 1e-6);  // v00
  EXPECT_NEAR(bilerp(0, 1, 0), 0.2f, 1e-6);  // v01
  EXPECT_NEAR(bilerp(1, 0, 0), 0.3f, 1e-6);  // v10
  EXPECT_NEAR(bilerp(1, 1, 2), 0.6f, 1e-6);  // v11
  EXPECT_NEAR(bilerp(0.25f, 0.5f, 1), 0.75f * 0.5f * 0.1f + 0.75f * 0.5f * 0.2f + 0.25f * 0.5f * 0.3f + 0.25f * 0.5f * 0.5f,
              1e-6);
  EXPECT_NEAR(channel(largest_value(corners), 2), 0.6f, 1e-6);
}

// pbrt-v3's MixTexture and ScaleTexture over two patterns: at every lookup the
// formula of the parts' own values; a 2D part makes the whole read (u, v).
TEST(ProceduralTexture, MixAndProductOfPatternsAreTheirFormulas) {
  auto texture = [](Pattern pattern) { return std::make_shared<const ProceduralTexture>(ProceduralTexture{"", pattern}); };
  const Pattern checks = CheckerboardPattern{Mapping2D{}, grey(0.9f), grey(0.2f), false};
  const Pattern dots = DotsPattern{Mapping2D{}, grey(0.7f), sg::from_raw<Reflectance>(sg::vec3_rep(0.1f, 0.3f, 0.5f))};
  const Pattern noise = FbmPattern{};
  const Pattern blend = MixPattern{{grey(1), texture(checks)}, {grey(0.5f), texture(dots)}, {grey(1), texture(noise)}};
  const Pattern product = ProductPattern{{grey(0.8f), texture(checks)}, {grey(1), texture(dots)}};
  EXPECT_TRUE(reads_uv(blend));
  EXPECT_TRUE(reads_uv(product));
  EXPECT_FALSE(reads_uv(MixPattern{{grey(1), texture(noise)}, {grey(0.2f), nullptr}, {grey(0.5f), nullptr}}));
  int checked = 0;
  for (int i = 0; i < 40; ++i) {
    const PatternLookup at{.u = Real(0.37) * i - 3, .v = Real(0.29) * i - 5,
                           .position = sg::from_raw<PointWorld>(sg::vec3_rep(0.11f * i, 0.07f * i, -0.05f * i))};
    const Real amount = channel(evaluate_unclamped(noise, at), 0);
    for (int c = 0; c < 3; ++c) {
      const Real a = channel(evaluate(checks, at), c), b = 0.5f * channel(evaluate(dots, at), c);
      const Real mixed = std::max((1 - amount) * a + amount * b, Real(0));
      EXPECT_NEAR(channel(evaluate(blend, at), c), mixed, 1e-6) << i << ", " << c;
      EXPECT_NEAR(channel(evaluate(product, at), c), 0.8f * a * channel(evaluate(dots, at), c), 1e-6) << i << ", " << c;
      checked += amount != 0;
    }
  }
  EXPECT_GT(checked, 60);  // the noise amount is not zero at most lookups
  EXPECT_NEAR(channel(largest_value(product), 0), 0.8f * 0.9f * 0.7f, 1e-6);
  EXPECT_NEAR(channel(largest_value(blend), 0), 0.9f, 1e-6);
}

}  // namespace
}  // namespace safegi::render
