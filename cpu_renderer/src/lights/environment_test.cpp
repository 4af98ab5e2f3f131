// The environment light's importance sampling: the density a sample reports is
// the one pdf() gives at its direction, it integrates to one over the sphere
// (the lat-long Jacobian 2π² sin θ included), and radiance / pdf averages to
// the radiance integrated over the sphere.
#include "lights/environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace safegi::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// ∫ g(ω) dω over the sphere by the midpoint rule in (θ, φ).
template <class G>
double sphere_integral(G g, int theta_steps = 400, int phi_steps = 800) {
  double sum = 0;
  const double dtheta = kPiD / theta_steps, dphi = 2 * kPiD / phi_steps;
  for (int i = 0; i < theta_steps; ++i) {
    double theta = (i + 0.5) * dtheta;
    for (int j = 0; j < phi_steps; ++j) {
      double phi = (j + 0.5) * dphi;
      DirectionWorld w(static_cast<Real>(std::sin(theta) * std::cos(phi)), static_cast<Real>(std::sin(theta) * std::sin(phi)),
                       static_cast<Real>(std::cos(theta)));
      sum += g(w) * std::sin(theta) * dtheta * dphi;
    }
  }
  return sum;
}

// A dim sky with one bright texel (a "sun") and a black band.
EnvironmentLight sunny_sky(bool rotated) {
  Image image{16, 8, std::vector<float>(16 * 8 * 3, 0.2f)};
  for (int c = 0; c < 3; ++c) image.rgb[3 * (2 * 16 + 11) + c] = 50.0f;
  for (int x = 0; x < 16; ++x)
    for (int c = 0; c < 3; ++c) image.rgb[3 * (6 * 16 + x) + c] = 0.0f;
  EnvironmentLight light;
  light.radiance = Radiance(Real(2) * units::radiance_unit);
  light.map = std::make_shared<MipMap>(std::move(image), TextureWrap::longitude_latitude);
  if (rotated)
    light.render_from_light = RenderFromLight::rotation(Real(0.7) * units::radian, sg::normalize(vector<LightSpace, dim::dimensionless>(1, 2, 3)));
  return light;
}

TEST(Environment, SampledDensityIsTheReportedOne) {
  for (bool rotated : {false, true}) {
    EnvironmentLight light = sunny_sky(rotated);
    Environment environment(light);
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(0, 1);
    // A direction's round trip through the map rounds: a sample within a
    // rounding of a cell edge may come back in the neighbouring cell.
    int samples = 0, disagreeing = 0;
    for (int i = 0; i < 20000; ++i) {
      std::optional<Environment::Sample> s = environment.sample(u(rng), u(rng));
      if (!s) continue;
      ++samples;
      double reported = sg::raw(environment.pdf(s->wi));
      double looked_up = sg::raw(environment.radiance(s->wi)).g;
      disagreeing += std::abs(sg::raw(s->pdf) - reported) > 1e-4 * reported ||
                     std::abs(sg::raw(s->radiance).g - looked_up) > 1e-3 * looked_up;
    }
    EXPECT_GT(samples, 19990) << rotated;
    EXPECT_LT(disagreeing, samples / 1000) << rotated;
  }
}

TEST(Environment, DensityIntegratesToOneOverTheSphere) {
  for (bool rotated : {false, true}) {
    EnvironmentLight light = sunny_sky(rotated);
    Environment environment(light);
    EXPECT_NEAR(sphere_integral([&](DirectionWorld w) { return sg::raw(environment.pdf(w)); }), 1.0, 2e-3) << rotated;
  }
  EnvironmentLight constant;
  constant.radiance = Radiance(Real(1) * units::radiance_unit);
  Environment uniform(constant);
  EXPECT_NEAR(sphere_integral([&](DirectionWorld w) { return sg::raw(uniform.pdf(w)); }, 100, 200), 1.0, 1e-4);
}

TEST(Environment, RadianceOverDensityAveragesToTheIntegral) {
  EnvironmentLight light = sunny_sky(true);
  Environment environment(light);
  double integral = sphere_integral([&](DirectionWorld w) { return sg::raw(environment.radiance(w)).g; });
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(0, 1);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    std::optional<Environment::Sample> s = environment.sample(u(rng), u(rng));
    double v = s ? sg::raw(s->radiance).g / sg::raw(s->pdf) : 0.0;
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / n, standard_error = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, integral, 5 * standard_error + 1e-3 * integral);
  // Importance sampling pays: the estimate's spread is far below uniform sampling's.
  EXPECT_LT(standard_error / mean, 0.01);
  // The mean radiance used for light choice is that integral over 4π.
  EXPECT_NEAR(sg::raw(environment.average_radiance()).g, integral / (4 * kPiD), 0.01 * integral / (4 * kPiD));
}

// Pole and seam: light space +z is row 0, φ = 0 is column 0's left edge.
TEST(Environment, LatLongLayout) {
  Image image{4, 2, {}};
  for (int i = 0; i < 8; ++i) image.rgb.insert(image.rgb.end(), {float(i), 0.0f, 0.0f});
  EnvironmentLight light;
  light.radiance = Radiance(Real(1) * units::radiance_unit);
  light.map = std::make_shared<MipMap>(std::move(image), TextureWrap::longitude_latitude);
  Environment environment(light);
  // θ = π/4 (v = 1/4: row 0's centre), φ = π/4 (u = 1/8: column 0's centre): texel 0.
  const Real s = std::sqrt(Real(0.5));
  EXPECT_NEAR(sg::raw(environment.radiance(DirectionWorld(s * s, s * s, s))).r, 0.0f, 1e-5f);
  // θ = 3π/4, φ = 5π/4 (u = 5/8: column 2): texel 4 + 2 = 6.
  EXPECT_NEAR(sg::raw(environment.radiance(DirectionWorld(-s * s, -s * s, -s))).r, 6.0f, 1e-4f);
}

}  // namespace
}  // namespace safegi::render
