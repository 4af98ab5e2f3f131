// Whole renders of mix materials against closed forms: in a white furnace a
// convex object's pixels are the environment's radiance times what one
// bounce keeps, which for a mix is the amount-weighted sum of its parts'
// albedos, per channel (pbrt-v3's MixMaterial), whichever part each hit picks.
#include <gtest/gtest.h>

#include <string>

#include "materials/material_mix.hpp"
#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// `materials` (JSON) on a 1 m sphere named "ball" in a furnace of 1.5 W/(m² sr):
// the centre's mean per channel must be `albedo` · 1.5 within 5 standard
// errors (each under 1 %), under the path, direct and photon integrators and
// every estimator knob.
void expect_furnace_albedo(const std::string& materials, const double (&albedo)[3]) {
  const double sky = 1.5;
  const std::string scene = R"json({
    "render": {"resolution": [24, 24], "integrator": "path", "max_depth": 8, "photons": 2000},
    "camera": {"position": ["0 m", "0 m", "4 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"},
    "materials": )json" + materials + R"json(,
    "shapes": [{"type": "sphere", "material": "ball", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
    "lights": [{"type": "environment", "radiance": "1.5 W/(m2 sr)"}]})json";
  for (IntegratorType integrator : {IntegratorType::path, IntegratorType::direct, IntegratorType::photon})
    for (const Knobs& knobs : estimator_knobs()) {
      auto adjust = [&](RenderSettings& s) {
        knobs.apply(s);
        s.integrator = integrator;
      };
      const Image on_sphere = render_text(scene, 512, 2, CropWindow{8, 8, 8, 8}, adjust);
      for (int c = 0; c < 3; ++c) {
        const double expected = albedo[c] * sky;
        const Estimate e = channel_estimate(on_sphere, c);
        EXPECT_NEAR(e.mean, expected, 5 * e.standard_error + 1e-6)
            << "integrator " << static_cast<int>(integrator) << ", " << knobs.name << ", channel " << c;
        EXPECT_LT(e.standard_error, 0.01 * expected)
            << "integrator " << static_cast<int>(integrator) << ", " << knobs.name << ", channel " << c;
      }
    }
}

// A mirror and a Lambertian part under a coloured amount: a ρ + (1 − a) r,
// the specular part and the diffuse one each found only on the hits that
// pick them, and weighted by a/p or (1 − a)/(1 − p) with p the amount's mean.
TEST(RenderMix, MirrorAndLambertUnderAColouredAmount) {
  const double amount[3] = {0.2, 0.5, 0.9}, rho[3] = {0.2, 0.4, 0.6}, r[3] = {0.9, 0.7, 0.5};
  double albedo[3];
  for (int c = 0; c < 3; ++c) albedo[c] = amount[c] * rho[c] + (1 - amount[c]) * r[c];
  expect_furnace_albedo(R"json({
      "ball": {"type": "mix", "first": "paint", "second": "chrome", "amount": [0.2, 0.5, 0.9]},
      "paint": {"type": "lambert", "reflectance": [0.2, 0.4, 0.6]},
      "chrome": {"type": "mirror", "reflectance": [0.9, 0.7, 0.5]}})json",
                        albedo);
}

// A mix inside a mix, grey amounts: 0.25 · (0.5 · 0.8 + 0.5 · 0.2) + 0.75 · 0.4.
TEST(RenderMix, NestedMixesOfLamberts) {
  const double albedo[3] = {0.425, 0.425, 0.425};
  expect_furnace_albedo(R"json({
      "ball": {"type": "mix", "first": "inner", "second": "grey", "amount": 0.25},
      "inner": {"type": "mix", "first": "light", "second": "dark", "amount": 0.5},
      "light": {"type": "lambert", "reflectance": 0.8},
      "dark": {"type": "lambert", "reflectance": 0.2},
      "grey": {"type": "lambert", "reflectance": 0.4}})json",
                        albedo);
}

// The pick is a fair coin of the amount's probability: over many hits the
// share of the first part is the amount, and the same hit always picks alike.
TEST(RenderMix, ChoiceNumbersAreUniformAndRepeatable) {
  int below[4] = {};
  const int count = 100000;
  for (int i = 0; i < count; ++i) {
    const Real x = static_cast<Real>(i % 317) * 0.01f, y = static_cast<Real>(i / 317) * 0.013f;
    const PointWorld p(x * units::metre, y * units::metre, Real(0.5) * units::metre);
    const DirectionWorld d = sg::normalize(vector<World, dim::dimensionless>(0.3f, -1, 0.2f + x));
    const Real u = mix_choice_number(p, d, 3);
    ASSERT_GE(u, 0);
    ASSERT_LT(u, 1);
    ASSERT_EQ(u, mix_choice_number(p, d, 3));
    for (int q = 0; q < 4; ++q) below[q] += u < 0.2f * static_cast<Real>(q + 1);
  }
  // Binomial: 4 standard deviations of n p (1 − p) at most 0.0016 n.
  for (int q = 0; q < 4; ++q) EXPECT_NEAR(below[q] / double(count), 0.2 * (q + 1), 0.0064) << q;
}

}  // namespace
}  // namespace safegi::render
