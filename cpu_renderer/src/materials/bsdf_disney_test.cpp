// pbrt-v3's Disney BSDF (disney.hpp): its limits against formulas written
// out here in double (Burley's 2012 diffuse in angles, the anisotropic GGX in
// slopes, the clearcoat), reciprocity, the energy it scatters (the white
// furnace) over a grid of parameters, its sampling against its pdf and the
// pdf's integral, and the lobes it picks among as pbrt-v3 does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "materials/bsdf.hpp"
#include "materials/bsdf_test_support.hpp"

namespace safegi::render {
namespace {

using namespace bsdf_test;

Material disney_material(const DisneyMaterial& d) {
  Material m;
  m.model = d;
  return m;
}

Reflectance grey(Real v) { return Reflectance(v); }

std::string describe(const DisneyMaterial& d) {
  return "metallic " + std::to_string(d.metallic) + " roughness " + std::to_string(d.roughness) + " sheen " +
         std::to_string(d.sheen) + " clearcoat " + std::to_string(d.clearcoat) + " spectrans " +
         std::to_string(d.spec_trans) + " anisotropic " + std::to_string(d.anisotropic);
}

double schlick(double cos_theta) { return std::pow(std::clamp(1 - cos_theta, 0.0, 1.0), 5); }

// Burley 2012's diffuse in angles: c/π (1 + (F_D90 − 1)(1 − cos θi)⁵)(1 +
// (F_D90 − 1)(1 − cos θo)⁵), F_D90 = ½ + 2 roughness cos²θd.
double burley_diffuse(double c, double roughness, double theta_o, double phi_o, double theta_i, double phi_i) {
  const double cos_angle = std::sin(theta_o) * std::sin(theta_i) * std::cos(phi_o - phi_i) +
                           std::cos(theta_o) * std::cos(theta_i);  // ωo·ωi = cos 2θd
  const double cos2_d = (1 + cos_angle) / 2;
  const double fd90 = 0.5 + 2 * roughness * cos2_d;
  return c / kPiD * (1 + (fd90 - 1) * schlick(std::cos(theta_i))) * (1 + (fd90 - 1) * schlick(std::cos(theta_o)));
}

// With metallic, sheen, clearcoat and spectrans 0 and η = 1 (the specular
// lobe's dielectric Fresnel factor vanishes) the BSDF is Burley's diffuse.
TEST(Disney, WithoutSpecularIsBurleysDiffuse) {
  for (double roughness : {0.0, 0.3, 0.5, 1.0}) {
    DisneyMaterial d;
    d.eta = 1;
    d.roughness = static_cast<Real>(roughness);
    const Material material = disney_material(d);
    const Reflectance colour(0.7f, 0.4f, 0.2f);
    const Bsdf bsdf(material, colour, false);
    for (double theta_o : {0.0, 0.4, 1.0, 1.45})
      for (double theta_i : {0.1, 0.7, 1.2, 1.5})
        for (double phi_i : {0.0, 1.0, 2.5, 3.1}) {
          const double phi_o = 0.3;
          const glm::dvec3 f(sg::raw(bsdf.eval(spherical(theta_o, phi_o), spherical(theta_i, phi_i))));
          const double c[3] = {0.7, 0.4, 0.2};
          for (int k = 0; k < 3; ++k) {
            const double expected = burley_diffuse(c[k], roughness, theta_o, phi_o, theta_i, phi_i);
            EXPECT_NEAR(f[k], expected, 2e-5 * (1 + expected)) << roughness << " " << theta_o << " " << theta_i;
          }
        }
  }
}

// A thin surface of flatness 1 and no diffuse transmission (difftrans 0),
// without specular reflection (η 1): Hanrahan and Krueger's approximation as
// Burley 2015 flattens it, c/π · 1.25 (F_ss (1/(cos θo + cos θi) − ½) + ½),
// F_ss = (1 + (F_ss90 − 1)(1 − cos θo)⁵)(1 + (F_ss90 − 1)(1 − cos θi)⁵),
// F_ss90 = roughness cos²θd, plus the retro-reflection (Burley's diffuse at
// roughness r minus its roughness-0 form); with difftrans 2 everything
// diffuse but the retro-reflection goes through, c/π below.
TEST(Disney, ThinIsTheFakeSubsurfaceLobeAndLambertTransmission) {
  const double roughness = 0.6, c = 0.7;
  DisneyMaterial d;
  d.eta = 1;
  d.roughness = static_cast<Real>(roughness);
  d.thin = true;
  d.flatness = 1;
  d.diff_trans = 0;
  const Material flat = disney_material(d);
  d.flatness = 0.3f;
  d.diff_trans = 2;
  const Material through = disney_material(d);
  for (double theta_o : {0.0, 0.5, 1.2})
    for (double theta_i : {0.2, 0.9, 1.4})
      for (double phi_i : {0.0, 1.5, 3.0}) {
        const double phi_o = 0.7;
        const DirectionShading wo = spherical(theta_o, phi_o), wi = spherical(theta_i, phi_i);
        const double cos_angle = glm::dot(glm::dvec3(sg::raw(wo)), glm::dvec3(sg::raw(wi)));
        const double cos2_d = (1 + cos_angle) / 2;
        const double f90 = roughness * cos2_d;
        const double fss = (1 + (f90 - 1) * schlick(std::cos(theta_o))) * (1 + (f90 - 1) * schlick(std::cos(theta_i)));
        const double ss = 1.25 * (fss * (1 / (std::cos(theta_o) + std::cos(theta_i)) - 0.5) + 0.5);
        const double retro = burley_diffuse(c, roughness, theta_o, phi_o, theta_i, phi_i) -
                             burley_diffuse(c, 0, theta_o, phi_o, theta_i, phi_i);
        const double expected = c / kPiD * ss + retro;
        EXPECT_NEAR(sg::raw(Bsdf(flat, grey(static_cast<Real>(c)), false).eval(wo, wi)).g, expected, 2e-5 * (1 + expected))
            << theta_o << " " << theta_i << " " << phi_i;
        const Reflectance through_colour = grey(static_cast<Real>(c));  // Bsdf keeps a reference to it
        const Bsdf thin(through, through_colour, false);
        EXPECT_TRUE(thin.transmits());
        EXPECT_NEAR(sg::raw(thin.eval(wo, -wi)).g, c / kPiD, 1e-6);
        EXPECT_NEAR(sg::raw(thin.eval(wo, wi)).g, retro, 2e-5 * (1 + retro));
      }
}

// Metallic 1 without diffuse: Schlick's F from the colour times the
// anisotropic GGX's D (in slopes: 1 / (π αx αy cos⁴θh (1 + tan²θh (cos²φh/αx²
// + sin²φh/αy²))²)) and Smith's separable G1 G1, Λ from the projected
// roughness √(αx² cos²φ + αy² sin²φ); αx = r²/aspect, αy = r² aspect.
TEST(Disney, MetallicIsAnisotropicGgxWithSchlicksFresnel) {
  DisneyMaterial d;
  d.metallic = 1;
  d.roughness = 0.6f;
  d.anisotropic = 0.8f;
  const Material material = disney_material(d);
  const double c = 0.8;
  const Reflectance albedo = grey(static_cast<Real>(c));  // Bsdf keeps a reference to it
  const Bsdf bsdf(material, albedo, false);
  const double aspect = std::sqrt(1 - 0.9 * 0.8), ax = 0.36 / aspect, ay = 0.36 * aspect;
  auto lambda = [&](double theta, double phi) {
    const double a2 = ax * ax * std::cos(phi) * std::cos(phi) + ay * ay * std::sin(phi) * std::sin(phi);
    const double t = std::tan(theta);
    return (std::sqrt(1 + a2 * t * t) - 1) / 2;
  };
  for (double theta_o : {0.2, 0.9, 1.3})
    for (double theta_i : {0.3, 0.8, 1.4})
      for (double phi_i : {0.5, 2.0, 4.0}) {
        const double phi_o = 1.1;
        const DirectionShading wo = spherical(theta_o, phi_o), wi = spherical(theta_i, phi_i);
        const glm::dvec3 o(sg::raw(wo)), i(sg::raw(wi));
        const glm::dvec3 h = glm::normalize(o + i);
        const double theta_h = std::acos(h.z), phi_h = std::atan2(h.y, h.x);
        const double t2 = std::tan(theta_h) * std::tan(theta_h);
        const double cos_h = std::cos(theta_h);
        const double e = 1 + t2 * (std::cos(phi_h) * std::cos(phi_h) / (ax * ax) + std::sin(phi_h) * std::sin(phi_h) / (ay * ay));
        const double D = 1 / (kPiD * ax * ay * std::pow(cos_h, 4) * e * e);
        const double G = 1 / (1 + lambda(theta_o, phi_o)) / (1 + lambda(theta_i, phi_i));
        const double F = c + (1 - c) * schlick(glm::dot(i, h));
        const double expected = F * D * G / (4 * std::cos(theta_o) * std::cos(theta_i));
        EXPECT_NEAR(sg::raw(bsdf.eval(wo, wi)).g, expected, 1e-4 * expected) << theta_o << " " << theta_i << " " << phi_i;
      }
}

// pbrt-v3's FrDielectric(cos θi, ηi, ηt): the indices swap when cos θi < 0.
double fr_dielectric(double cos_i, double eta_i, double eta_t) {
  cos_i = std::clamp(cos_i, -1.0, 1.0);
  if (cos_i < 0) std::swap(eta_i, eta_t), cos_i = -cos_i;
  const double sin_t = eta_i / eta_t * std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
  if (sin_t >= 1) return 1;
  const double cos_t = std::sqrt(std::max(0.0, 1 - sin_t * sin_t));
  const double parallel = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  const double perpendicular = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  return (parallel * parallel + perpendicular * perpendicular) / 2;
}

// spectrans 1, metallic 0 (no diffuse): pbrt-v3's MicrofacetReflection with
// DisneyFresnel, here FrDielectric(ωi·h, 1, η), and MicrofacetTransmission
// with FresnelDielectric(1, η) and T = √c, for radiance: (1 − F(ωo·h)) D G
// |ωo·h| |ωi·h| / (|cos θo cos θi| (ωo·h + η' ωi·h)²), η' = η seen from
// outside, 1/η from inside, written in pbrt-v3's frame (+z its outside; seen
// from inside, ωo.z < 0 and h is turned to +z), D and G (separable) isotropic.
TEST(Disney, DielectricLobesArePbrtV3sMicrofacetReflectionAndTransmission) {
  DisneyMaterial d;
  d.spec_trans = 1;
  d.roughness = 0.55f;
  d.eta = 1.4f;
  const Material material = disney_material(d);
  const double c = 0.64, eta = 1.4, alpha = 0.55 * 0.55;
  auto D = [&](const glm::dvec3& h) {
    const double c2 = h.z * h.z, a2 = alpha * alpha, e = c2 * (a2 - 1) + 1;
    return a2 / (kPiD * e * e);
  };
  auto G1 = [&](const glm::dvec3& w) {
    const double c2 = w.z * w.z, tan2 = (1 - c2) / c2;
    return 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
  };
  int compared[2] = {0, 0};
  for (bool from_inside : {false, true}) {
    const Reflectance albedo = grey(static_cast<Real>(c));  // Bsdf keeps a reference to it
    const Bsdf bsdf(material, albedo, from_inside);
    const double sign = from_inside ? -1 : 1;  // ours to pbrt-v3's frame
    for (double theta_o : {0.1, 0.7, 1.2})
      for (double theta_i : {0.2, 0.6, 1.1, 1.45})
        for (double phi_i : {0.3, 2.0, 3.0}) {
          const DirectionShading wo = spherical(theta_o, 0.1), wi = spherical(theta_i, phi_i);
          const glm::dvec3 o = sign * glm::dvec3(sg::raw(wo)), i = sign * glm::dvec3(sg::raw(wi));
          // Reflection (both on wo's side).
          glm::dvec3 h = glm::normalize(o + i);
          if (h.z < 0) h = -h;  // pbrt-v3's Faceforward(wh, (0, 0, 1))
          const double reflected = fr_dielectric(glm::dot(i, h), 1, eta) * D(h) * G1(o) * G1(i) / (4 * std::abs(o.z * i.z));
          EXPECT_NEAR(sg::raw(bsdf.eval(wo, wi)).g, reflected, 1e-4 * reflected + 1e-7)
              << from_inside << " " << theta_o << " " << theta_i << " " << phi_i;
          // Transmission (wi on the other side).
          const glm::dvec3 t = -i;
          const double e = o.z > 0 ? eta : 1 / eta;
          glm::dvec3 ht = glm::normalize(o + t * e);
          if (ht.z < 0) ht = -ht;
          double transmitted = 0;
          if (glm::dot(o, ht) * glm::dot(t, ht) < 0) {
            const double denominator = glm::dot(o, ht) + e * glm::dot(t, ht);
            const double factor = 1 / e;  // TransportMode::Radiance
            transmitted = std::sqrt(c) * (1 - fr_dielectric(glm::dot(o, ht), 1, eta)) *
                          std::abs(D(ht) * G1(o) * G1(t) * e * e * std::abs(glm::dot(t, ht)) * std::abs(glm::dot(o, ht)) *
                                   factor * factor / (o.z * t.z * denominator * denominator));
          }
          // pbrt-v3 counts facets that ωo sees from behind, which we leave out (as translucent does).
          // (Ours refract where ωo·h > 0, h turned to our normal's side: −ht from inside.)
          if (sign * glm::dot(o, ht) <= 0 && transmitted > 0) continue;
          if (transmitted > 0) ++compared[from_inside];
          EXPECT_NEAR(sg::raw(bsdf.eval(wo, -wi)).g, transmitted, 1e-4 * transmitted + 1e-7)
              << from_inside << " " << theta_o << " " << theta_i << " " << phi_i << " (through)";
        }
  }
  EXPECT_GE(compared[0], 8);  // of 36 pairs each way (10 and 12 have a transmission there)
  EXPECT_GE(compared[1], 8);
  std::printf("transmission compared at %d pairs from outside, %d from inside\n", compared[0], compared[1]);
}

// The clearcoat adds ¼ clearcoat (0.04 + 0.96 (1 − ωo·h)⁵) D_GTR1 G1 G1 / (4
// cos θo cos θi), α = lerp(clearcoatgloss, 0.1, 0.001), G1 the GGX's of α 0.25.
TEST(Disney, ClearcoatIsGtr1) {
  DisneyMaterial base;
  base.roughness = 0.4f;
  DisneyMaterial coated = base;
  coated.clearcoat = 0.7f;
  coated.clearcoat_gloss = 0.3f;
  const Material plain = disney_material(base), coat = disney_material(coated);
  const Reflectance colour = grey(0.5f);
  const double alpha = 0.7 * 0.1 + 0.3 * 0.001, a2 = alpha * alpha;
  auto g1 = [](double cos_theta) {
    const double tan2 = (1 - cos_theta * cos_theta) / (cos_theta * cos_theta);
    return 2 / (1 + std::sqrt(1 + 0.0625 * tan2));
  };
  for (double theta_o : {0.1, 0.8, 1.4})
    for (double theta_i : {0.2, 0.9, 1.3}) {
      const DirectionShading wo = spherical(theta_o, 0.0), wi = spherical(theta_i, 2.9);
      const glm::dvec3 o(sg::raw(wo)), i(sg::raw(wi));
      const glm::dvec3 h = glm::normalize(o + i);
      const double D = (a2 - 1) / (kPiD * std::log(a2) * (1 + (a2 - 1) * h.z * h.z));
      const double F = 0.04 + 0.96 * schlick(glm::dot(o, h));
      const double expected = 0.25 * 0.7 * F * D * g1(o.z) * g1(i.z) / (4 * o.z * i.z);
      const double added = sg::raw(Bsdf(coat, colour, false).eval(wo, wi)).g - sg::raw(Bsdf(plain, colour, false).eval(wo, wi)).g;
      EXPECT_NEAR(added, expected, 1e-4 * expected + 1e-6) << theta_o << " " << theta_i;
    }
}

// f(ωo, ωi) = f(ωi, ωo) on either side; across the interface, from inside
// and back, radiance's BTDF differs by η² (1/η² of radiance entering the denser side).
TEST(Disney, Reciprocal) {
  DisneyMaterial d;
  d.metallic = 0.3f;
  d.roughness = 0.45f;
  d.anisotropic = 0.5f;
  d.sheen = 0.8f;
  d.clearcoat = 1;
  d.clearcoat_gloss = 0.4f;
  d.spec_trans = 0.6f;
  d.specular_tint = 0.5f;
  DisneyMaterial thin_d = d;
  thin_d.thin = true, thin_d.flatness = 0.6f, thin_d.diff_trans = 0.7f;
  for (const DisneyMaterial& dd : {d, thin_d}) {
  const Material material = disney_material(dd);
  const Reflectance colour(0.9f, 0.5f, 0.3f);
  const double pairs[][2] = {{0.1, 0.3}, {0.1, 0.5}, {0.6, 0.3}, {0.6, 0.9}, {1.2, 0.9}, {1.2, 1.0}, {1.5, 0.2}};
  for (const auto& [a, b] : pairs)
    for (bool from_inside : {false, true}) {
      const Bsdf bsdf(material, colour, from_inside);
      const DirectionShading w1 = spherical(a, 0.2), w2 = spherical(b, 2.5);
      for (int c = 0; c < 3; ++c) {
        const double forward = sg::raw(bsdf.eval(w1, w2))[c], backward = sg::raw(bsdf.eval(w2, w1))[c];
        EXPECT_GT(forward, 0);
        EXPECT_NEAR(forward, backward, 1e-4 * forward) << a << ", " << b;
      }
    }
  for (const auto& [a, b] : pairs) {
    if (a > 1.4) continue;  // grazing from outside, steep inside: every such facet has ωo behind it (f = 0 both ways)
    const DirectionShading outside = spherical(a, 0.2), inside = spherical(b, 0.5);
    const double forward = sg::raw(Bsdf(material, colour, false).eval(outside, -inside)).g;
    const double backward = sg::raw(Bsdf(material, colour, true).eval(inside, -outside)).g;
    EXPECT_GT(forward, 0) << a << ", " << b;
    // (The thin surface's Lambert transmission is the same both ways: it adds (1 − η²) of it.)
    const double lambert = dd.thin ? 0.35 * 0.5 / kPiD * (1 - 1.5 * 1.5) : 0;
    EXPECT_NEAR(backward, 1.5 * 1.5 * forward + lambert, 1e-4 * backward) << a << ", " << b;
  }
  }
}

// ∫ f |cos θi| dωi over both hemispheres (the midpoint rule, 800 × 160 steps
// each; its error on these lobes, roughness ≥ 0.3, is below 0.01) of a white
// colour seen from outside, over a grid of the parameters. The lobes that
// conserve energy on their own do: the specular reflection alone (metallic
// 1; Schlick's F of white is 1), reflection and refraction at the dielectric
// interface (spectrans 1), Burley's diffuse without retro-reflection
// (roughness 0: (1 − Fo/2)(1 − Fi/2) ≤ 1) — each at most 1 + 0.01 — and the
// clearcoat adds at most its ¼. pbrt-v3's model sums its lobes without
// layering them (the diffuse lobes are not weighted by what the specular one
// reflects, nor the transmission by 1 − metallic), so the whole exceeds 1:
// over this grid up to 1.58 (roughness 1, sheen and clearcoat 1, at 86°; the
// test prints it). What is checked over the whole grid is that sum's bound:
// (1 − metallic)(1 − spectrans) times the diffuse lobes' own albedo (measured
// alone: metallic, spectrans 0, η 1) + 1 (specular) + spectrans
// (transmission) + ¼ clearcoat, + 0.02 (the grid's quadrature is coarser,
// 600 × 120 steps: it gives the metal of roughness 0.3 at 86° 1.012).
TEST(Disney, WhiteFurnaceLobesAtMostOneAndTheirSumBounded) {
  auto albedo_of = [](const DisneyMaterial& d, double theta, int steps = 800) {
    const Material material = disney_material(d);
    const Reflectance white = grey(1);  // Bsdf keeps a reference to it
    const Bsdf bsdf(material, white, false);
    const DirectionShading wo = spherical(theta, 0.4);
    return sphere_integral([&](DirectionShading wi) { return sg::raw(bsdf.eval(wo, wi)).g * std::abs(wi.z()); }, steps, steps / 5);
  };
  const double thetas[] = {0.0, 0.8, 1.3, 1.5};
  for (Real roughness : {0.3f, 0.6f, 1.0f})
    for (Real anisotropic : {0.0f, 0.8f})
      for (double theta : thetas) {
        DisneyMaterial metal;
        metal.metallic = 1, metal.roughness = roughness, metal.anisotropic = anisotropic;
        EXPECT_LE(albedo_of(metal, theta), 1.01) << describe(metal) << " at " << theta;
        DisneyMaterial dielectric = metal;
        dielectric.metallic = 0, dielectric.spec_trans = 1;
        EXPECT_LE(albedo_of(dielectric, theta), 1.01) << describe(dielectric) << " at " << theta;
        DisneyMaterial coated = dielectric;
        coated.clearcoat = 1, coated.clearcoat_gloss = 0;
        EXPECT_LE(albedo_of(coated, theta) - albedo_of(dielectric, theta), 0.25) << describe(coated) << " at " << theta;
      }
  for (double theta : thetas) {
    DisneyMaterial burley;
    burley.roughness = 0, burley.eta = 1;  // no retro-reflection, no specular reflection
    EXPECT_LE(albedo_of(burley, theta), 1.01) << theta;
  }
  double largest = 0, largest_diffuse = 0;
  std::string where_largest;
  for (Real metallic : {0.0f, 0.5f, 1.0f})
    for (Real roughness : {0.3f, 0.6f, 1.0f})
      for (Real sheen : {0.0f, 1.0f})
        for (Real clearcoat : {0.0f, 1.0f})
          for (Real spec_trans : {0.0f, 1.0f}) {
            DisneyMaterial d;
            d.metallic = metallic, d.roughness = roughness, d.sheen = sheen;
            d.clearcoat = clearcoat, d.clearcoat_gloss = 0, d.spec_trans = spec_trans, d.specular_tint = 1;
            DisneyMaterial diffuse_lobes = d;
            diffuse_lobes.metallic = 0, diffuse_lobes.spec_trans = 0, diffuse_lobes.eta = 1, diffuse_lobes.clearcoat = 0;
            for (double theta : thetas) {
              const double albedo = albedo_of(d, theta, 600), diffuse = albedo_of(diffuse_lobes, theta, 600);
              const std::string where = describe(d) + " at " + std::to_string(theta);
              if (albedo > largest) largest = albedo, where_largest = where;
              largest_diffuse = std::max(largest_diffuse, diffuse);
              const double bound = (1 - metallic) * (1 - spec_trans) * diffuse + 1 + spec_trans + clearcoat / 4;
              EXPECT_LE(albedo, bound + 0.02) << where;
            }
          }
  std::printf("largest albedo of the diffuse lobes alone: %.4f\n", largest_diffuse);
  std::printf("largest white-furnace albedo over the grid: %.4f (%s)\n", largest, where_largest.c_str());
}

// Sampling: each sample's pdf is pdf() at its direction, its weight f |cos θ|
// / pdf; the weights average to the quadrature's albedo (within 1 % + 2e-3:
// 100000 samples); pdf() integrates over the sphere to the share of samples
// drawn (within 5e-3: the quadrature's error), which is at most 1.
TEST(Disney, SamplesItsPdfWhichIntegratesToAtMostOne) {
  std::mt19937 rng(44);
  std::uniform_real_distribution<Real> u(0, 1);
  std::vector<DisneyMaterial> sets(5);
  sets[0].roughness = 0.5f;                                             // pbrt-v3's defaults but roughness
  sets[1].metallic = 0.4f, sets[1].roughness = 0.6f, sets[1].sheen = 1;  // every reflecting lobe
  sets[1].clearcoat = 1, sets[1].clearcoat_gloss = 0, sets[1].specular_tint = 0.5f;
  sets[2].spec_trans = 0.7f, sets[2].roughness = 0.55f;  // refracting too
  sets[3].metallic = 1, sets[3].roughness = 0.7f, sets[3].anisotropic = 0.9f;
  sets[4].thin = true, sets[4].flatness = 0.5f, sets[4].diff_trans = 0.8f, sets[4].spec_trans = 0.4f;  // thin
  sets[4].roughness = 0.8f, sets[4].sheen = 0.5f;
  const Reflectance colour(0.8f, 0.6f, 0.3f);
  for (const DisneyMaterial& d : sets) {
    const Material material = disney_material(d);
    for (bool from_inside : {false, true}) {
      const Bsdf bsdf(material, colour, from_inside);
      EXPECT_EQ(bsdf.transmits(), d.spec_trans > 0 || d.thin);
      EXPECT_FALSE(bsdf.is_specular());
      for (double theta : {0.0, 0.7, 1.3}) {
        const DirectionShading wo = spherical(theta, 0.4);
        const double albedo =
            sphere_integral([&](DirectionShading wi) { return sg::raw(bsdf.eval(wo, wi)).g * std::abs(wi.z()); }, 1000, 180);
        const double pdf_total = sphere_integral([&](DirectionShading wi) { return sg::raw(bsdf.pdf(wo, wi)); }, 1000, 180);
        const int n = 100000;
        double weights = 0, mismatch = 0;
        int drawn = 0;
        for (int i = 0; i < n; ++i) {
          std::optional<BsdfSample> s = bsdf.sample(wo, u(rng), u(rng), u(rng));
          if (!s) continue;
          ++drawn;
          EXPECT_FALSE(s->specular);
          weights += sg::raw(s->weight).g;
          const double reported = sg::raw(bsdf.pdf(wo, s->wi));
          mismatch = std::max(mismatch, std::abs(sg::raw(s->pdf) - reported) / reported);
          const double expected = sg::raw(bsdf.eval(wo, s->wi)).g * std::abs(s->wi.z()) / sg::raw(s->pdf);
          EXPECT_NEAR(sg::raw(s->weight).g, expected, 1e-5 * (1 + expected));
        }
        const std::string where = describe(d) + (from_inside ? " inside at " : " outside at ") + std::to_string(theta);
        EXPECT_NEAR(weights / n, albedo, 0.01 * albedo + 2e-3) << where;
        EXPECT_LT(mismatch, 1e-4) << where;
        EXPECT_NEAR(pdf_total, static_cast<double>(drawn) / n, 5e-3) << where;
        EXPECT_LE(pdf_total, 1 + 5e-3) << where;
      }
    }
  }
}

// pbrt-v3's DisneyMaterial adds the diffuse, retro-reflection and (with
// sheen) sheen lobes where (1 − metallic)(1 − spectrans) > 0, always the
// specular reflection, the clearcoat where it is above 0 and the transmission
// where spectrans is; BSDF::Sample_f picks one uniformly.
TEST(Disney, HasPbrtV3sLobes) {
  const Reflectance colour = grey(0.5f);
  DisneyMaterial d;
  EXPECT_EQ(DisneyBsdf(d, colour, false).lobe_count(), 3);
  d.sheen = 0.5f;
  d.clearcoat = 0.5f;
  EXPECT_EQ(DisneyBsdf(d, colour, false).lobe_count(), 5);
  d.spec_trans = 1;  // no diffuse weight left
  const DisneyBsdf through(d, colour, false);
  ASSERT_EQ(through.lobe_count(), 3);
  EXPECT_EQ(through.lobe(0), DisneyLobe::specular);
  EXPECT_EQ(through.lobe(1), DisneyLobe::clearcoat);
  EXPECT_EQ(through.lobe(2), DisneyLobe::transmission);
  EXPECT_EQ(through.eta(), 1.5f);
  EXPECT_EQ(DisneyBsdf(d, colour, true).eta(), 1 / 1.5f);
  d = DisneyMaterial{};
  d.metallic = 1;
  EXPECT_EQ(DisneyBsdf(d, colour, false).lobe_count(), 1);
  // Thin: the fake subsurface lobe after the diffuse one, the Lambert transmission last, always.
  d.metallic = 0;
  d.thin = true;
  d.spec_trans = 0.5f;
  const DisneyBsdf thin(d, colour, false);
  ASSERT_EQ(thin.lobe_count(), 6);
  EXPECT_EQ(thin.lobe(1), DisneyLobe::fake_subsurface);
  EXPECT_EQ(thin.lobe(4), DisneyLobe::transmission);
  EXPECT_EQ(thin.lobe(5), DisneyLobe::diffuse_transmission);
  // Its refraction's roughness is (0.65 η − 0.35) roughness: 0.625 · 0.5; height-correlated masking.
  EXPECT_NEAR(thin.transmission_facets().alpha_x(), 0.3125 * 0.3125, 1e-6);
  EXPECT_NEAR(thin.facets().alpha_x(), 0.25, 1e-6);
  // pbrt-v3's alphas: max(0.001, r²/aspect), max(0.001, r² aspect), aspect = √(1 − 0.9 anisotropic).
  d.roughness = 0.5f;
  d.anisotropic = 0.5f;
  const DisneyBsdf anisotropic(d, colour, false);
  EXPECT_NEAR(anisotropic.facets().alpha_x(), 0.25 / std::sqrt(0.55), 1e-6);
  EXPECT_NEAR(anisotropic.facets().alpha_y(), 0.25 * std::sqrt(0.55), 1e-6);
  d.roughness = 0;
  EXPECT_EQ(DisneyBsdf(d, colour, false).facets().alpha_x(), 0.001f);
}

}  // namespace
}  // namespace safegi::render
