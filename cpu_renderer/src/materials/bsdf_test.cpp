// The BSDFs against closed forms and against each other: Fresnel's values,
// Snell's law, the microfacet distribution's normalisation, and for every
// sampled material that its sampling density is the one pdf() reports and
// that its sample weights average to the albedo a quadrature of eval() gives.
#include "materials/bsdf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <algorithm>
#include <random>
#include <vector>

#include "materials/bsdf_test_support.hpp"

namespace safegi::render {
namespace {

using namespace bsdf_test;

TEST(Fresnel, NormalIncidenceIsTheSquaredIndexContrast) {
  for (double n : {1.33, 1.5, 2.42}) {
    double expected = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    EXPECT_NEAR(fresnel_dielectric(1, static_cast<Real>(n)), expected, 1e-6) << n;
    EXPECT_NEAR(fresnel_dielectric(1, static_cast<Real>(1 / n)), expected, 1e-6) << "from inside, " << n;
  }
  EXPECT_NEAR(fresnel_dielectric(1, 1.5f), 0.04, 1e-7);
}

TEST(Fresnel, GrazingIncidenceReflectsEverything) {
  for (Real eta : {1.33f, 1.5f, 2.42f}) {
    EXPECT_NEAR(fresnel_dielectric(1e-4f, eta), 1, 1e-3) << eta;
    EXPECT_EQ(fresnel_dielectric(0, eta), 1) << eta;
    // Rising monotonically from Brewster's angle, where the parallel part vanishes, to 1.
    Real previous = fresnel_dielectric(std::cos(std::atan(eta)), eta);
    for (int i = 1; i <= 100; ++i) {
      double theta = std::atan(eta) + (kPiD / 2 - std::atan(eta)) * i / 100;
      Real r = fresnel_dielectric(static_cast<Real>(std::cos(theta)), eta);
      EXPECT_GE(r, previous);
      previous = r;
    }
  }
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double critical = std::asin(1 / 1.5);
  EXPECT_EQ(fresnel_dielectric(static_cast<Real>(std::cos(critical + 1e-3)), 1 / 1.5f), 1);
  EXPECT_LT(fresnel_dielectric(static_cast<Real>(std::cos(critical - 1e-2)), 1 / 1.5f), 1);
  EXPECT_FALSE(refract(spherical(critical + 1e-3, 0.3), 1 / 1.5f));
}

// Stokes: the interface reflects alike whichever way light crosses it, so
// transmittance 1 - R agrees on both sides of a refraction.
TEST(Fresnel, ReciprocalAcrossTheInterface) {
  for (double theta = 0.05; theta < 1.5; theta += 0.1) {
    DirectionShading wo = spherical(theta, 1.0);
    std::optional<DirectionShading> wt = refract(wo, 1.5f);
    ASSERT_TRUE(wt);
    EXPECT_NEAR(fresnel_dielectric(wo.z(), 1.5f), fresnel_dielectric(-wt->z(), 1 / 1.5f), 1e-5) << theta;
  }
}

// A conductor's reflectance from the Fresnel equations with a complex index
// n = η + ik, written directly (Born & Wolf): cos θt from Snell's law in the
// complex plane, then the s and p amplitudes. Independent of the rearranged
// real arithmetic of pbrt-v3's FrConductor that fresnel_conductor follows.
double complex_fresnel(double cos_i, double eta, double k) {
  const std::complex<double> n(eta, k);
  const double sin2_i = 1 - cos_i * cos_i;
  const std::complex<double> cos_t = std::sqrt(1.0 - sin2_i / (n * n));
  const std::complex<double> s = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  const std::complex<double> p = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  return (std::norm(s) + std::norm(p)) / 2;
}

// Copper's, gold's and aluminium's η and k (pbrt-v3's RGB, red and blue), a
// dielectric (k = 0) and a near-perfect conductor.
constexpr double kConductors[][2] = {{0.2, 3.9}, {1.1, 2.14}, {0.14, 3.97}, {1.44, 1.6}, {1.65, 9.2}, {1.5, 0}, {1, 1000}};

TEST(Fresnel, ConductorAtNormalIncidenceIsTheIndexContrast) {
  for (const auto& [eta, k] : kConductors) {
    double expected = ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
    EXPECT_NEAR(fresnel_conductor(1, static_cast<Real>(eta), static_cast<Real>(k)), expected, 1e-6) << eta << ", " << k;
  }
}

TEST(Fresnel, ConductorFollowsTheComplexFresnelEquations) {
  for (const auto& [eta, k] : kConductors)
    for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0, 89.0, 89.9}) {
      double cos_i = std::cos(degrees * kPiD / 180);
      double expected = complex_fresnel(cos_i, eta, k);
      EXPECT_NEAR(fresnel_conductor(static_cast<Real>(cos_i), static_cast<Real>(eta), static_cast<Real>(k)), expected,
                  2e-6)
          << eta << ", " << k << " at " << degrees << " deg";
    }
  // Grazing light is reflected entirely, and with k = 0 it is the dielectric's value.
  for (const auto& [eta, k] : kConductors)
    EXPECT_NEAR(fresnel_conductor(0, static_cast<Real>(eta), static_cast<Real>(k)), 1, 1e-6) << eta << ", " << k;
  for (double cos_i : {1.0, 0.7, 0.3, 0.05})
    EXPECT_NEAR(fresnel_conductor(static_cast<Real>(cos_i), 1.5f, 0), fresnel_dielectric(static_cast<Real>(cos_i), 1.5f),
                1e-6)
        << cos_i;
  // Per channel on spectra.
  Reflectance rgb = fresnel_conductor(0.5f, IndexSpectrum(0.2f, 0.92f, 1.1f), IndexSpectrum(3.9f, 2.45f, 2.14f));
  EXPECT_NEAR(rgb.r(), complex_fresnel(0.5, 0.2f, 3.9f), 2e-6);
  EXPECT_NEAR(rgb.g(), complex_fresnel(0.5, 0.92f, 2.45f), 2e-6);
  EXPECT_NEAR(rgb.b(), complex_fresnel(0.5, 1.1f, 2.14f), 2e-6);
}

TEST(Refract, SnellsLaw) {
  for (double theta = 0; theta < 1.55; theta += 0.05) {
    DirectionShading wo = spherical(theta, 0.7);
    std::optional<DirectionShading> wt = refract(wo, 1.5f);
    ASSERT_TRUE(wt);
    double sin_t = std::sqrt(wt->x() * wt->x() + wt->y() * wt->y());
    EXPECT_NEAR(std::sin(theta), 1.5 * sin_t, 1e-6) << theta;
    EXPECT_LT(wt->z(), 0);
    // In the plane of incidence, on the other side of the normal.
    EXPECT_NEAR(wt->x() * wo.y() - wt->y() * wo.x(), 0, 1e-6);
    EXPECT_LE(wt->x() * wo.x() + wt->y() * wo.y(), 1e-7);
    EXPECT_NEAR(wt->x() * wt->x() + wt->y() * wt->y() + wt->z() * wt->z(), 1, 1e-6);
  }
}

TEST(TrowbridgeReitz, NormalsIntegrateToOneOverProjectedSolidAngle) {
  for (Real alpha : {0.05f, 0.3f, 1.0f}) {
    TrowbridgeReitz distribution(alpha);
    double total = hemisphere_integral(
        [&](DirectionShading h) { return sg::raw(distribution.density(h)) * h.z(); }, alpha < 0.1f ? 6000 : 1500);
    EXPECT_NEAR(total, 1.0, 2e-3) << alpha;
  }
}

TEST(TrowbridgeReitz, SampledNormalsFollowTheirDensity) {
  // The fraction of sampled normals within θ < θ0 against ∫ pdf over that cap.
  TrowbridgeReitz distribution(0.3f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 1);
  const int n = 200000;
  for (double theta0 : {0.1, 0.3, 0.6, 1.0}) {
    int inside = 0;
    for (int i = 0; i < n; ++i) inside += std::acos(distribution.sample_normal(u(rng), u(rng)).z()) < theta0;
    double cap = hemisphere_integral(
        [&](DirectionShading h) { return std::acos(h.z()) < theta0 ? sg::raw(distribution.normal_pdf(h)) : 0.0; });
    EXPECT_NEAR(static_cast<double>(inside) / n, cap, 4e-3) << theta0;
  }
}

// The normals a direction sees: their density integrates to 1 over the
// normals (Smith's masking is what normalises it: ∫ D(h) max(0, ωo·h) dωh =
// cos θo (1 + Λ(ωo))), and sampled ones follow it, about the normal and about ωo.
TEST(TrowbridgeReitz, VisibleNormalsIntegrateToOneAndFollowTheirDensity) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, 1);
  const int n = 200000;
  for (Real alpha : {0.05f, 0.3f, 1.0f}) {
    TrowbridgeReitz distribution(alpha);
    for (double theta_o : {0.0, 0.7, 1.4}) {
      DirectionShading wo = spherical(theta_o, 0.5);
      auto pdf = [&](DirectionShading h) { return sg::raw(distribution.visible_normal_pdf(wo, h)); };
      EXPECT_NEAR(hemisphere_integral(pdf, alpha < 0.1f ? 6000 : 1500), 1.0, 3e-3) << alpha << " at " << theta_o;
      std::vector<DirectionShading> normals;
      for (int i = 0; i < n; ++i) normals.push_back(distribution.sample_visible_normal(wo, u(rng), u(rng)));
      for (double theta0 : {0.1, 0.3, 0.6, 1.0}) {
        int near_normal = 0, near_wo = 0;
        for (DirectionShading h : normals) {
          near_normal += std::acos(h.z()) < theta0;
          near_wo += sg::dot(h, wo) > std::cos(theta0);
        }
        double cap_normal = hemisphere_integral([&](DirectionShading h) { return std::acos(h.z()) < theta0 ? pdf(h) : 0.0; });
        double cap_wo = hemisphere_integral([&](DirectionShading h) { return sg::dot(h, wo) > std::cos(theta0) ? pdf(h) : 0.0; });
        EXPECT_NEAR(static_cast<double>(near_normal) / n, cap_normal, 5e-3) << alpha << " at " << theta_o << ", " << theta0;
        EXPECT_NEAR(static_cast<double>(near_wo) / n, cap_wo, 5e-3) << alpha << " at " << theta_o << ", " << theta0;
      }
    }
  }
}

// The lobed materials the tests compare, with the same diffuse and specular parts.
const TexturedReflectance kTestDiffuse{Reflectance(0.5f, 0.4f, 0.3f)};
const Reflectance kTestSpecular(0.4f);
Material lambert_material() { return {LambertMaterial{kTestDiffuse}}; }
Material oren_nayar_material() {
  return {OrenNayarMaterial::with_sigma(kTestDiffuse, Real(30) * units::degree)};
}
Material phong_material() { return {PhongMaterial{kTestDiffuse, kTestSpecular, 40}}; }
PlasticMaterial plastic_parameters() { return PlasticMaterial{kTestDiffuse, kTestSpecular, 0.2f}; }
Material plastic_material() { return {plastic_parameters()}; }
// Copper (pbrt-v3's RGB η and k), rough enough for the quadrature below.
Material copper_material(Real alpha = 0.2f) {
  return {ConductorMaterial{IndexSpectrum(0.2f, 0.92f, 1.1f), IndexSpectrum(3.9f, 2.45f, 2.14f), alpha}};
}
SubstrateMaterial substrate_parameters() { return SubstrateMaterial{kTestDiffuse, kTestSpecular, 0.2f}; }
Material substrate_material() { return {substrate_parameters()}; }

struct SampledEstimate {
  double mean_weight, pdf_mismatch;
};
// The average sample weight (an unbiased estimate of the albedo) and the
// largest relative difference between a sample's pdf and pdf() at its direction.
SampledEstimate estimate_albedo(const Bsdf& bsdf, DirectionShading wo, int n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(0, 1);
  double sum = 0, mismatch = 0;
  for (int i = 0; i < n; ++i) {
    std::optional<BsdfSample> s = bsdf.sample(wo, u(rng), u(rng), u(rng));
    if (!s) continue;
    sum += sg::raw(s->weight).g;
    double reported = sg::raw(bsdf.pdf(wo, s->wi));
    mismatch = std::max(mismatch, std::abs(sg::raw(s->pdf) - reported) / reported);
    Reflectance expected = bsdf.eval(wo, s->wi) * sg::cos_theta(s->wi) / s->pdf;
    EXPECT_NEAR(sg::raw(s->weight).g, sg::raw(expected).g, 1e-5 * (1 + sg::raw(expected).g));
  }
  return {sum / n, mismatch};
}

TEST(Bsdf, SamplingAgreesWithEvaluation) {
  const Material materials[] = {lambert_material(), phong_material(), plastic_material(), copper_material(),
                                substrate_material(), oren_nayar_material()};
  for (int type = 0; type < 6; ++type) {
    const Material& m = materials[type];
    Bsdf bsdf(m);
    for (double theta : {0.0, 0.5, 1.0, 1.4}) {
      DirectionShading wo = spherical(theta, 0.4);
      double albedo = hemisphere_integral(
          [&](DirectionShading wi) { return sg::raw(bsdf.eval(wo, wi)).g * wi.z(); }, 1500, 180);
      double pdf_total = hemisphere_integral([&](DirectionShading wi) { return sg::raw(bsdf.pdf(wo, wi)); }, 1500, 180);
      SampledEstimate sampled = estimate_albedo(bsdf, wo, 100000);
      EXPECT_NEAR(sampled.mean_weight, albedo, 0.01 * albedo + 2e-3) << type << " at " << theta;
      EXPECT_LT(sampled.pdf_mismatch, 1e-4) << type << " at " << theta;
      EXPECT_LE(pdf_total, 1.0 + 5e-3) << type << " at " << theta;
      EXPECT_LE(albedo, 1.0) << type << " at " << theta;
      if (std::holds_alternative<LambertMaterial>(m.model)) {
        EXPECT_NEAR(albedo, 0.4, 1e-3);
        EXPECT_NEAR(pdf_total, 1.0, 1e-3);
      }
    }
  }
}

// Oren and Nayar's model as their paper and pbrt-v3 write it, in angles:
// ρ/π (A + B max(0, cos(φi − φo)) sin(max θ) tan(min θ)), transcribed in
// double; σ = 0 is exactly Lambert.
TEST(Bsdf, OrenNayarIsTheQualitativeModel) {
  const double rho = sg::raw(kTestDiffuse.value).g;
  for (double sigma_degrees : {0.0, 10.0, 30.0, 60.0}) {
    const OrenNayarMaterial parameters =
        OrenNayarMaterial::with_sigma(kTestDiffuse, static_cast<Real>(sigma_degrees) * units::degree);
    const Material material{parameters};
    const Bsdf bsdf(material);
    const double s2 = std::pow(sigma_degrees * kPiD / 180, 2);
    const double a = 1 - s2 / (2 * (s2 + 0.33)), b = 0.45 * s2 / (s2 + 0.09);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> theta(0.001, 1.56), phi(0, 2 * kPiD);
    for (int i = 0; i < 2000; ++i) {
      const double to = theta(rng), ti = theta(rng), po = phi(rng), pi = phi(rng);
      const double expected =
          rho / kPiD * (a + b * std::max(0.0, std::cos(pi - po)) * std::sin(std::max(ti, to)) * std::tan(std::min(ti, to)));
      const double f = sg::raw(bsdf.eval(spherical(to, po), spherical(ti, pi))).g;
      ASSERT_NEAR(f, expected, 2e-5 * expected + 1e-6) << sigma_degrees << " degrees, pair " << i;
    }
    if (sigma_degrees == 0) {
      const Material lambert_parameters = lambert_material();
      const Bsdf lambert(lambert_parameters);
      const DirectionShading wo = spherical(0.3, 0.2), wi = spherical(1.1, 2.5);
      EXPECT_EQ(sg::raw(bsdf.eval(wo, wi)), sg::raw(lambert.eval(wo, wi)));
    }
  }
  // Rougher, it sends more light back towards the light at grazing angles
  // (retro-reflection) and less than Lambert straight up from grazing light.
  const Material rough_material = oren_nayar_material(), flat_material = lambert_material();
  const Bsdf rough(rough_material), flat(flat_material);
  const DirectionShading grazing = spherical(1.3, 0), back = spherical(1.3, 0), up = spherical(0, 0);
  EXPECT_GT(sg::raw(rough.eval(grazing, back)).g, sg::raw(flat.eval(grazing, back)).g);
  EXPECT_LT(sg::raw(rough.eval(up, grazing)).g, sg::raw(flat.eval(up, grazing)).g);
}

TEST(Bsdf, PlasticWithoutSpecularIsLambert) {
  PlasticMaterial parameters = plastic_parameters();
  parameters.specular = Reflectance{};
  Material plastic{parameters}, lambert = lambert_material();
  Bsdf a(plastic), b(lambert);
  for (double theta : {0.2, 0.9}) {
    DirectionShading wo = spherical(theta, 0.1), wi = spherical(0.7, 2.0);
    EXPECT_EQ(sg::raw(a.eval(wo, wi)), sg::raw(b.eval(wo, wi)));
    EXPECT_EQ(sg::raw(a.pdf(wo, wi)), sg::raw(b.pdf(wo, wi)));
  }
}

// The coating reflects (ρs-weighted) Fresnel's share: at normal incidence a
// smooth-ish lobe's specular albedo is about ρs · F(0) = ρs · 0.04; pbrt-v3's
// swapped indices give the same at normal incidence and total reflection
// beyond 41.8°.
TEST(Bsdf, PlasticCoatingFresnel) {
  PlasticMaterial m = plastic_parameters();
  m.diffuse = TexturedReflectance{};
  m.specular = Reflectance(1.0f);
  m.alpha = 0.02f;
  auto specular_albedo = [&](const PlasticMaterial& parameters, double theta) {
    Material mat{parameters};
    Bsdf bsdf(mat);
    DirectionShading wo = spherical(theta, 0.0);
    return estimate_albedo(bsdf, wo, 100000).mean_weight;
  };
  EXPECT_NEAR(specular_albedo(m, 0.01), 0.04, 2e-3);
  EXPECT_NEAR(specular_albedo(m, 0.6), fresnel_dielectric(std::cos(0.6f), 1.5f), 4e-3);
  m.pbrt_v3_fresnel = true;
  EXPECT_NEAR(specular_albedo(m, 0.01), 0.04, 2e-3);
  EXPECT_GT(specular_albedo(m, 0.9), 0.9);  // beyond the critical angle of 1.5 -> 1: everything
  // Seen from the side its normal points away from, pbrt-v3's Fresnel gets a
  // negative cosine and swaps the indices back: the coating's own reflectance.
  Material swapped{m};
  const Reflectance black{};
  Bsdf from_inside(swapped, black, true);
  EXPECT_NEAR(estimate_albedo(from_inside, spherical(0.9, 0.0), 100000).mean_weight,
              specular_albedo(PlasticMaterial{m.diffuse, m.specular, m.alpha, m.ior, false}, 0.9), 4e-3);
}

// The metal's lobe with F = 1 (k = 1000: F >= 1 − 4e-6) in a white furnace:
// the directional albedo ∫ f cos θi dωi is what a path gains, and a single
// Smith-masked microfacet bounce only loses energy (the light it masks is not
// scattered again), most at high roughness and grazing angles. Estimated from
// 400000 samples each (4 standard errors allowed: 0.7 % of 1 − ln 2, which a
// 1 % error exceeds); at α = 0.01 nearly nothing
// is masked: above 0.995 up to 80° from the normal (measured 0.9999 at normal
// incidence, 0.9978 at 80°). At α = 1 and normal incidence D = 1/π and
// G = 2 cos θi / (1 + cos θi), so the albedo is ∫₀¹ μ/(1 + μ) dμ = 1 − ln 2.
TEST(Bsdf, RoughMetalLobeNeverGainsEnergy) {
  for (Real alpha : {0.01f, 0.139f, 0.3f, 0.6f, 1.0f}) {
    Material mirror_like{ConductorMaterial{IndexSpectrum(1.0f), IndexSpectrum(1000.0f), alpha}};
    Bsdf bsdf(mirror_like);
    for (double theta : {0.0, 0.5, 1.0, 1.4}) {
      DirectionShading wo = spherical(theta, 0.3);
      std::mt19937 rng(5);
      std::uniform_real_distribution<Real> u(0, 1);
      const int n = 400000;
      double sum = 0, sum2 = 0;
      for (int i = 0; i < n; ++i) {
        std::optional<BsdfSample> s = bsdf.sample(wo, u(rng), u(rng), u(rng));
        double w = s ? sg::raw(s->weight).g : 0;
        sum += w;
        sum2 += w * w;
      }
      double mean = sum / n, standard_error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      EXPECT_LE(mean, 1 + 4 * standard_error) << "alpha " << alpha << " at " << theta;
      if (alpha <= 0.01f) {
        EXPECT_GT(mean, 0.995) << "alpha " << alpha << " at " << theta;
      }
      if (alpha == 1.0f && theta == 0.0) {
        EXPECT_NEAR(mean, 1 - std::log(2.0), 4 * standard_error);
      }
    }
  }
}

// pbrt-v3's FresnelBlend (Ashikhmin and Shirley) and its Pdf, written out
// here in double from their formulas, at one pair of directions and per
// channel (a coloured ρs too): f = 28/(23π) ρd (1 − ρs) (1 − (1 − cos θi/2)⁵)
// (1 − (1 − cos θo/2)⁵) + D(h) / (4 |ωi·h| max(cos θi, cos θo)) (ρs + (1 − ρs)
// (1 − ωi·h)⁵); pdf = ½ (cos θi/π + D(h) G1(ωo) |ωo·h| / cos θo / (4 ωo·h)),
// the visible-normal density pbrt-v3's TrowbridgeReitzDistribution samples.
TEST(Bsdf, SubstrateIsPbrtV3FresnelBlend) {
  const double alpha = 0.3, kd[3] = {0.5, 0.4, 0.3}, ks[3] = {0.4, 0.2, 0.05};
  const Material substrate{SubstrateMaterial{TexturedReflectance{Reflectance(0.5f, 0.4f, 0.3f)},
                                             Reflectance(0.4f, 0.2f, 0.05f), static_cast<Real>(alpha)}};
  Bsdf bsdf(substrate);
  const double theta_o = 0.6, phi_o = 0.2, theta_i = 1.1, phi_i = 2.5;
  const double o[3] = {std::sin(theta_o) * std::cos(phi_o), std::sin(theta_o) * std::sin(phi_o), std::cos(theta_o)};
  const double i[3] = {std::sin(theta_i) * std::cos(phi_i), std::sin(theta_i) * std::sin(phi_i), std::cos(theta_i)};
  double h[3] = {o[0] + i[0], o[1] + i[1], o[2] + i[2]};
  const double h_length = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (double& c : h) c /= h_length;
  const double cos_h = i[0] * h[0] + i[1] * h[1] + i[2] * h[2], a2 = alpha * alpha;
  const double d = a2 / (kPiD * std::pow(h[2] * h[2] * (a2 - 1) + 1, 2));
  auto pow5 = [](double v) { return std::pow(v, 5); };
  DirectionShading wo = spherical(theta_o, phi_o), wi = spherical(theta_i, phi_i);
  glm::vec3 f = sg::raw(bsdf.eval(wo, wi));
  for (int c = 0; c < 3; ++c) {
    double diffuse = 28 / (23 * kPiD) * kd[c] * (1 - ks[c]) * (1 - pow5(1 - i[2] / 2)) * (1 - pow5(1 - o[2] / 2));
    double specular = d / (4 * cos_h * std::max(i[2], o[2])) * (ks[c] + (1 - ks[c]) * pow5(1 - cos_h));
    EXPECT_NEAR(f[c], diffuse + specular, 1e-5 * (diffuse + specular)) << c;
  }
  EXPECT_NEAR(f[0], 0.13820, 1e-4);  // the value itself, for a reader to check
  const double g1 = 2 / (1 + std::sqrt(1 + a2 * std::pow(std::tan(theta_o), 2)));
  const double pdf = 0.5 * (i[2] / kPiD + d * g1 * cos_h / o[2] / (4 * cos_h));
  EXPECT_NEAR(sg::raw(bsdf.pdf(wo, wi)), pdf, 1e-5 * pdf);
  // Reciprocal: both parts are symmetric in ωo and ωi (ωi·h = ωo·h).
  glm::vec3 backward = sg::raw(bsdf.eval(wi, wo));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(backward[c], f[c], 1e-5 * f[c]) << c;
  EXPECT_FALSE(bsdf.is_specular());
}

// The substrate's diffuse part is the Bsdf's given diffuse value (a texel,
// where Kd is textured), and it samples half and half whatever its parts'
// sizes, as pbrt-v3 does: plastic's lobe choice by ρs / (ρd + ρs) does not
// apply. ∫ pdf is the share of samples that stay above the surface: all the
// cosine half's, and the reflections of visible normals that do.
TEST(Bsdf, SubstrateTakesTheTexelAndSamplesHalfAndHalf) {
  const Reflectance texel(0.1f, 0.2f, 0.9f);
  SubstrateMaterial given = substrate_parameters(), textured = given;
  textured.diffuse.value = texel;
  const Material substrate{given}, expected{textured};
  Bsdf with_texel(substrate, texel, false), as_expected(expected);
  DirectionShading wo = spherical(0.4, 0.1), wi = spherical(0.9, 2.0);
  EXPECT_EQ(sg::raw(with_texel.eval(wo, wi)), sg::raw(as_expected.eval(wo, wi)));
  EXPECT_NE(sg::raw(with_texel.eval(wo, wi)), sg::raw(Bsdf(substrate).eval(wo, wi)));

  SubstrateMaterial diffuse_only = given, glossy_only = given;
  diffuse_only.specular = Reflectance{};
  glossy_only.diffuse = TexturedReflectance{};
  const Material a{diffuse_only}, b{glossy_only};
  for (double theta : {0.2, 1.2}) {
    DirectionShading w = spherical(theta, 0.7);
    EXPECT_EQ(sg::raw(Bsdf(a).pdf(w, wi)), sg::raw(Bsdf(substrate).pdf(w, wi)));
    EXPECT_EQ(sg::raw(Bsdf(b).pdf(w, wi)), sg::raw(Bsdf(substrate).pdf(w, wi)));
  }
  // Below u_lobe = 1/2 the cosine-weighted hemisphere, whatever the parts.
  for (const Material* m : {&a, &b, &substrate}) {
    std::optional<BsdfSample> s = Bsdf(*m).sample(wo, 0.49f, 0.3f, 0.8f);
    ASSERT_TRUE(s);
    EXPECT_EQ(sg::raw(s->wi), sg::raw(from_kernel<DirectionShading>(sample_cosine_hemisphere(0.3f, 0.8f))));
  }

  Bsdf bsdf(substrate);
  std::mt19937 rng(13);
  std::uniform_real_distribution<Real> u(0, 1);
  for (double theta : {0.0, 0.7, 1.4}) {
    DirectionShading w = spherical(theta, 0.3);
    const int n = 200000;
    int above = 0;
    for (int k = 0; k < n; ++k) above += bsdf.sample(w, u(rng), u(rng), u(rng)).has_value();
    double pdf_total = hemisphere_integral([&](DirectionShading v) { return sg::raw(bsdf.pdf(w, v)); }, 1500, 180);
    EXPECT_NEAR(pdf_total, static_cast<double>(above) / n, 4e-3) << theta;
    EXPECT_GE(pdf_total, 0.5 - 2e-3) << theta;
  }
}

// Helmholtz reciprocity: f(ωo, ωi) = f(ωi, ωo) (F at ωi·h = ωo·h, G symmetric).
TEST(Bsdf, MetalIsReciprocal) {
  Material copper = copper_material(0.3f);
  Bsdf bsdf(copper);
  for (double a : {0.1, 0.6, 1.2})
    for (double b : {0.3, 0.9, 1.4}) {
      DirectionShading wo = spherical(a, 0.2), wi = spherical(b, 2.1);
      glm::vec3 forward = sg::raw(bsdf.eval(wo, wi)), backward = sg::raw(bsdf.eval(wi, wo));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(forward[c], backward[c], 1e-5 * forward[c]) << a << ", " << b;
    }
  EXPECT_FALSE(bsdf.is_specular());
}

TEST(Bsdf, GlassChoosesByFresnelAndCompressesRadiance) {
  const GlassMaterial parameters{Reflectance(1.0f), Reflectance(1.0f), 1.5f};
  const Material glass{parameters};
  const Reflectance no_diffuse{};
  for (bool from_inside : {false, true}) {
    const Real eta = from_inside ? 1 / parameters.ior : parameters.ior;
    Bsdf bsdf(glass, no_diffuse, from_inside);
    EXPECT_TRUE(bsdf.is_specular());
    for (double theta : {0.0, 0.6, 1.2}) {
      DirectionShading wo = spherical(theta, 0.3);
      double reflected = fresnel_dielectric(wo.z(), eta);
      int reflections = 0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) {
        Real u = (i + 0.5f) / n;
        std::optional<BsdfSample> s = bsdf.sample(wo, u, 0.5f, 0.5f);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->specular);
        if (s->wi.z() > 0) {
          ++reflections;
          EXPECT_FLOAT_EQ(sg::raw(s->weight).r, 1.0f);
        } else {
          EXPECT_FLOAT_EQ(sg::raw(s->weight).r, 1 / (eta * eta));
          std::optional<BsdfSample> flux = bsdf.sample(wo, u, 0.5f, 0.5f, Transport::importance);
          EXPECT_FLOAT_EQ(sg::raw(flux->weight).r, 1.0f);
        }
      }
      EXPECT_NEAR(static_cast<double>(reflections) / n, reflected, 1.0 / n + 1e-6) << eta << " at " << theta;
    }
  }
}

// Both of glass's lobes at once (what direct lighting follows): each sample's
// direction, weighed by its Fresnel share, so that they sum to what sampling
// one by Fresnel gives in expectation; total internal reflection is one lobe
// of the whole tint; a mirror has one, a diffuse material none.
TEST(Bsdf, SpecularLobesAreTheFresnelWeightedSamples) {
  const GlassMaterial parameters{Reflectance(0.9f), Reflectance(0.8f), 1.5f};
  const Material glass{parameters};
  const Reflectance no_diffuse{};
  for (bool from_inside : {false, true}) {
    const Real eta = from_inside ? 1 / parameters.ior : parameters.ior;
    Bsdf bsdf(glass, no_diffuse, from_inside);
    for (double theta : {0.0, 0.6, 1.2}) {
      const DirectionShading wo = spherical(theta, 0.3);
      const SpecularLobes lobes = bsdf.specular_lobes(wo);
      const Real reflected = fresnel_dielectric(wo.z(), eta);
      const std::optional<BsdfSample> reflection = bsdf.sample(wo, 0, 0.5f, 0.5f);
      ASSERT_GE(lobes.count, 1);
      EXPECT_EQ(sg::raw(lobes.lobe[0].wi), sg::raw(reflection->wi));
      if (reflected == 1) {  // beyond the critical angle
        EXPECT_EQ(lobes.count, 1) << eta << " at " << theta;
        EXPECT_FLOAT_EQ(sg::raw(lobes.lobe[0].weight).r, 0.9f);
        continue;
      }
      ASSERT_EQ(lobes.count, 2) << eta << " at " << theta;
      const std::optional<BsdfSample> refraction = bsdf.sample(wo, 1, 0.5f, 0.5f);
      EXPECT_FLOAT_EQ(sg::raw(lobes.lobe[0].weight).r, 0.9f * reflected);
      EXPECT_EQ(sg::raw(lobes.lobe[1].wi), sg::raw(refraction->wi));
      EXPECT_FLOAT_EQ(sg::raw(lobes.lobe[1].weight).r, 0.8f * (1 - reflected) / (eta * eta));
      EXPECT_EQ(lobes.lobe[1].eta, eta);
      EXPECT_EQ(refraction->eta, eta);
      EXPECT_TRUE(lobes.lobe[0].specular && lobes.lobe[1].specular);
    }
  }
  const Material mirror{MirrorMaterial{Reflectance(0.7f)}};
  const SpecularLobes mirrored = Bsdf(mirror).specular_lobes(spherical(0.4, 0.1));
  ASSERT_EQ(mirrored.count, 1);
  EXPECT_FLOAT_EQ(sg::raw(mirrored.lobe[0].weight).g, 0.7f);
  const Material lambert{LambertMaterial{}};
  const Reflectance grey(0.5f);
  EXPECT_EQ(Bsdf(lambert, grey, false).specular_lobes(spherical(0.4, 0.1)).count, 0);
}

}  // namespace
}  // namespace safegi::render
