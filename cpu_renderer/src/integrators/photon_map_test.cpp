// Photon emission and the density estimate's kernel: photons carry, on
// average, exactly the power of their lights, and the kernel integrates to one
// over its disc.
#include "integrators/photon_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;

TEST(PhotonMap, ConeKernelIntegratesToOneOverItsDisc) {
  const Length radius = Real(0.3) * units::metre;
  double total = 0;
  const int steps = 100000;
  for (int i = 0; i < steps; ++i) {
    double d = (i + 0.5) / steps * 0.3;
    total += sg::raw(cone_kernel(Real(d) * units::metre, radius)) * 2 * kPiD * d * (0.3 / steps);
  }
  EXPECT_NEAR(total, 1.0, 1e-6);
  EXPECT_NEAR(sg::raw(cone_kernel(sg::zero, radius)), 3 / (kPiD * 0.09), 1e-4);
  EXPECT_EQ(sg::raw(cone_kernel(radius, radius)), 0);
}

// The mean flux of emitted photons is the scene's total emitted power:
// point light 4π I, one-sided area light π L A (two-sided: twice), and for the
// environment the flux through the disc across the scene, π R² · 4π L.
TEST(PhotonMap, PhotonsCarryTheirLightsPower) {
  Scene scene = parse_scene(R"json({
    "camera": {"position": ["0 m", "0 m", "5 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"},
    "shapes": [
      {"type": "quad", "origin": ["-1 m", "-1 m", "0 m"], "edge_u": ["2 m", "0 m", "0 m"], "edge_v": ["0 m", "1 m", "0 m"],
       "emission": "3 W/(m2 sr)"},
      {"type": "sphere", "center": ["0 m", "2 m", "0 m"], "radius": "0.5 m", "emission": "1 W/(m2 sr)", "two_sided": true}],
    "lights": [{"type": "point", "position": ["0 m", "1 m", "1 m"], "intensity": "2 W/sr"},
               {"type": "environment", "radiance": "0.25 W/(m2 sr)"}]})json",
                            "test.json", ".");
  Lights lights(scene);
  // The scene's bounding box: x in [-1, 1], y in [-1, 2.5], z in [-0.5, 0.5] (the sphere).
  const double radius = 0.5 * std::sqrt(2.0 * 2.0 + 3.5 * 3.5 + 1.0 * 1.0);
  const double expected = 3 * kPiD * 2 + 2 * kPiD * 1 * 4 * kPiD * 0.25 + 4 * kPiD * 2 +
                          kPiD * radius * radius * 4 * kPiD * 0.25;
  std::mt19937 rng(1);
  std::uniform_real_distribution<Real> u(0, 1);
  const int n = 400000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    std::optional<PhotonEmission> photon = lights.sample_emission(sg::zero, u(rng), u(rng), u(rng), u(rng), u(rng));
    double flux = photon ? sg::raw(photon->flux).g : 0.0;
    sum += flux;
    sum2 += flux * flux;
  }
  double mean = sum / n, standard_error = std::sqrt((sum2 / n - mean * mean) / n);
  // Lights are chosen by power, so every photon of these constant emitters
  // carries the same flux: the mean is exact up to rounding.
  EXPECT_NEAR(mean, expected, 5 * standard_error + 1e-5 * expected);
  EXPECT_LT(standard_error, 0.01 * expected);
}

}  // namespace
}  // namespace safegi::render
