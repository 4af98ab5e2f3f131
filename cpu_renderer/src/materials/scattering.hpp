// The physics under the materials: Fresnel reflectance of a smooth dielectric
// or conductor interface, refraction, and the Trowbridge–Reitz (GGX)
// microfacet distribution with Smith's masking, the sampling of its normals
// (all, or those a direction sees) and the Torrance–Sparrow reflection and
// Walter et al.'s refraction it gives, in the local shading space (normal = +z).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "safegi/cpu_renderer/sampling.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// The fraction of light a smooth dielectric interface reflects (unpolarised),
// for light arriving at cos θ_i > 0 from the side of the normal and relative
// index eta = n_far / n_near (n_near: the side the light comes from). Beyond
// the critical angle (eta < 1) it is total internal reflection: 1.
inline Real fresnel_dielectric(Real cos_i, Real eta) {
  cos_i = std::clamp(cos_i, Real(0), Real(1));
  const Real sin2_t = (1 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1) return 1;
  const Real cos_t = std::sqrt(std::max(Real(0), 1 - sin2_t));
  const Real parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const Real perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return (parallel * parallel + perpendicular * perpendicular) / 2;
}

// The fraction of light a smooth conductor reflects (unpolarised), light
// arriving at cos θ_i > 0 from a dielectric of index 1 onto a metal of complex
// index η + ik (relative to that dielectric): pbrt-v3's FrConductor for one
// channel, the exact Fresnel equations with a complex index. At normal
// incidence it is ((η − 1)² + k²) / ((η + 1)² + k²); k = 0 gives
// fresnel_dielectric's value.
inline Real fresnel_conductor(Real cos_i, Real eta, Real k) {
  cos_i = std::clamp(cos_i, Real(0), Real(1));
  const Real cos2 = cos_i * cos_i, sin2 = 1 - cos2;
  const Real eta2 = eta * eta, k2 = k * k;
  // a² + b² and a, where a + ib is the complex cosine of the refracted angle times the index.
  const Real t0 = eta2 - k2 - sin2;
  const Real a2_plus_b2 = std::sqrt(t0 * t0 + 4 * eta2 * k2);
  const Real a = std::sqrt(std::max(Real(0), (a2_plus_b2 + t0) / 2));
  const Real t1 = a2_plus_b2 + cos2, t2 = 2 * cos_i * a;
  const Real perpendicular = (t1 - t2) / (t1 + t2);
  const Real t3 = cos2 * a2_plus_b2 + sin2 * sin2, t4 = t2 * sin2;
  const Real parallel = perpendicular * (t3 - t4) / (t3 + t4);
  return (parallel + perpendicular) / 2;
}
// The same per channel: η and k are spectra (dimensionless), so is the reflectance.
inline Reflectance fresnel_conductor(Real cos_i, IndexSpectrum eta, IndexSpectrum k) {
  return Reflectance(fresnel_conductor(cos_i, eta.r(), k.r()), fresnel_conductor(cos_i, eta.g(), k.g()),
                     fresnel_conductor(cos_i, eta.b(), k.b()));
}

// Snell's law: the direction refracted from `wo` (pointing away from the
// surface on the normal's side, wo.z > 0) into the far side, eta = n_far / n_near;
// nothing under total internal reflection.
inline std::optional<DirectionShading> refract(DirectionShading wo, Real eta) {
  const Real cos_i = wo.z();
  const Real sin2_t = (1 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1) return std::nullopt;
  const Real cos_t = std::sqrt(std::max(Real(0), 1 - sin2_t));
  return DirectionShading(-wo.x() / eta, -wo.y() / eta, -cos_t);
}
// The same through a microfacet of normal h (ωo·h > 0): the tangential part
// shrinks by 1/η, the rest goes on along −h.
inline std::optional<DirectionShading> refract(DirectionShading wo, DirectionShading h, Real eta) {
  const Real along = sg::dot(wo, h);
  const Real sin2_t = std::max(Real(0), 1 - along * along) / (eta * eta);
  if (sin2_t >= 1) return std::nullopt;
  const Real depth = std::sqrt(std::max(Real(0), 1 - sin2_t));
  return sg::normalize(wo * (-1 / eta) + h * (along / eta - depth));
}

// Heitz's 2018 construction ("Sampling the GGX Distribution of Visible Normals"): a normal drawn
// from those ωo (cos θo > 0) sees under the GGX distribution of roughness (αx, αy).
inline DirectionShading sample_ggx_visible_normal(Real alpha_x, Real alpha_y, DirectionShading wo, Real u1, Real u2) {
  // ωo stretched to the configuration where alpha is 1 and the visible
  // normals are a hemisphere's, projected onto the disk across it.
  const Real vx0 = alpha_x * wo.x(), vy0 = alpha_y * wo.y();
  const Real v_length = std::sqrt(vx0 * vx0 + vy0 * vy0 + wo.z() * wo.z());
  const Real vx = vx0 / v_length, vy = vy0 / v_length, vz = wo.z() / v_length;
  const Real across = std::sqrt(vx * vx + vy * vy);
  const Real t1x = across > 0 ? -vy / across : Real(1), t1y = across > 0 ? vx / across : Real(0);
  const Real t2x = -vz * t1y, t2y = vz * t1x, t2z = vx * t1y - vy * t1x;  // V × T1
  // A uniform point on the disk, its half hidden behind the hemisphere squeezed by cos θ of V.
  const Real r = std::sqrt(u1), phi = 2 * kPi * u2;
  const Real p1 = r * std::cos(phi);
  const Real s = (1 + vz) / 2;
  const Real p2 = (1 - s) * std::sqrt(std::max(Real(0), 1 - p1 * p1)) + s * r * std::sin(phi);
  const Real p3 = std::sqrt(std::max(Real(0), 1 - p1 * p1 - p2 * p2));
  // Lifted onto the hemisphere, then unstretched.
  const Real nx = p1 * t1x + p2 * t2x + p3 * vx, ny = p1 * t1y + p2 * t2y + p3 * vy, nz = p2 * t2z + p3 * vz;
  return sg::from_raw<DirectionShading>(glm::normalize(sg::vec3_rep(alpha_x * nx, alpha_y * ny, std::max(Real(1e-6), nz))));
}

// The isotropic Trowbridge–Reitz (GGX) distribution of microfacet normals h
// with roughness alpha. D(h) is a density per projected solid angle of
// normals, ∫ D(h) cos θ_h dω_h = 1, hence its type.
class TrowbridgeReitz {
 public:
  explicit TrowbridgeReitz(Real alpha) : alpha_(alpha) {}

  quantity<dim::pdf_projected_solid_angle> density(DirectionShading h) const {
    const Real cos2 = h.z() * h.z();
    if (!(cos2 > 0)) return sg::zero;
    const Real a2 = alpha_ * alpha_;
    const Real denominator = cos2 * (a2 - 1) + 1;
    return a2 / (kPi * denominator * denominator) / units::steradian / units::proj;
  }

  // Smith's masking–shadowing, height-correlated: 1 / (1 + Λ(ωo) + Λ(ωi)).
  Real masking_shadowing(DirectionShading wo, DirectionShading wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }

  // A normal drawn with density D(h) cos θ_h per solid angle of normals.
  DirectionShading sample_normal(Real u1, Real u2) const {
    const Real tan2 = alpha_ * alpha_ * u1 / std::max(Real(1) - u1, Real(1e-12));
    const Real cos_theta = 1 / std::sqrt(1 + tan2);
    const Real sin_theta = std::sqrt(std::max(Real(0), 1 - cos_theta * cos_theta));
    const Real phi = 2 * kPi * u2;
    return DirectionShading(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
  }
  // The density of sample_normal, per solid angle of normals.
  PdfSolidAngle normal_pdf(DirectionShading h) const { return density(h) * sg::cos_theta(h); }

  // Torrance–Sparrow reflection by facets that reflect everything,
  // D(h) G(ωo, ωi) / (4 cos θo cos θi) with h the half vector of ωo and ωi: a
  // material multiplies it by its Fresnel factor at ωi·h. The two cosines are
  // the geometric factors of the microfacet derivation, plain ratios here: the
  // projected measure is D's, so the result is per projected solid angle, a BRDF's.
  quantity<dim::brdf> reflection(DirectionShading wo, DirectionShading wi, DirectionShading h) const {
    return masking_shadowing(wo, wi) / (4 * wo.z() * wi.z()) * density(h);
  }
  // ωo reflected about a normal drawn by sample_normal.
  DirectionShading sample_reflection(DirectionShading wo, Real u1, Real u2) const {
    DirectionShading h = sample_normal(u1, u2);
    return sg::from_raw<DirectionShading>(sg::raw(sg::reflect(wo, sg::to_normal(h))));
  }
  // The density of sample_reflection per solid angle of ωi, h their half vector.
  PdfSolidAngle reflection_pdf(DirectionShading wo, DirectionShading h) const;

  // Smith's masking of one direction (cos θ > 0): G1(ω) = 1 / (1 + Λ(ω)).
  Real masking(DirectionShading w) const { return 1 / (1 + lambda(w)); }

  // A normal drawn from those ωo (cos θo > 0) sees, the visible normals:
  // density D(h) G1(ωo) |ωo·h| / cos θo per solid angle of normals. That is
  // the density pbrt-v3's TrowbridgeReitzDistribution samples (its
  // sampleVisibleArea, on by default), which it draws by Heitz and d'Eon's
  // 2014 slopes; this draws it by Heitz's 2018 construction ("Sampling the
  // GGX Distribution of Visible Normals"): the same density, another map of (u1, u2).
  DirectionShading sample_visible_normal(DirectionShading wo, Real u1, Real u2) const {
    return sample_ggx_visible_normal(alpha_, alpha_, wo, u1, u2);
  }
  // The density of sample_visible_normal, per solid angle of normals. The
  // facet's area seen from ωo (ωo·h of it, G1 unmasked) over the surface's
  // (cos θo) stands where normal_pdf has cos θh: the projection that turns
  // D's projected measure into solid angle. Facets turned away (ωo·h < 0) are
  // never drawn: 0, where pbrt-v3's Pdf takes |ωo·h| (the same on the half
  // vectors of reflections, the only normals it is asked about).
  PdfSolidAngle visible_normal_pdf(DirectionShading wo, DirectionShading h) const {
    return density(h) * (masking(wo) * std::max(Real(0), sg::dot(wo, h)) / wo.z() * units::proj);
  }
  // ωo reflected about a visible normal; its density per solid angle of ωi,
  // h their half vector (pbrt-v3's Pdf(wo, wh) / (4 ωo·h)).
  DirectionShading sample_visible_reflection(DirectionShading wo, Real u1, Real u2) const {
    DirectionShading h = sample_visible_normal(wo, u1, u2);
    return sg::from_raw<DirectionShading>(sg::raw(sg::reflect(wo, sg::to_normal(h))));
  }
  PdfSolidAngle visible_reflection_pdf(DirectionShading wo, DirectionShading h) const;

  // Walter et al.'s refraction by facets that let everything through, for
  // radiance: D(h) G(ωo, ωi) |ωo·h| |ωi·h| / (|cos θo cos θi| (ωo·h + η ωi·h)²),
  // h the refraction's half vector, η = n_far / n_near (ωo's side is near);
  // a material multiplies it by 1 − F(ωo·h). Only facets ωo sees and ωi
  // leaves from behind count (ωo·h > 0 > ωi·h): the ones sampling draws. The
  // η² by which pbrt-v3's MicrofacetTransmission and Walter's BTDF start
  // cancels against the 1/η² of radiance crossing into the far side, so that
  // only importance (photons' flux) carries it: there the caller multiplies by η².
  quantity<dim::brdf> transmission(DirectionShading wo, DirectionShading wi, DirectionShading h, Real eta) const {
    const Real o_h = sg::dot(wo, h), i_h = sg::dot(wi, h);
    if (!(o_h > 0 && i_h < 0)) return sg::zero;
    const Real across = o_h + eta * i_h;
    return masking_shadowing(wo, wi) * std::abs(o_h * i_h / (wo.z() * wi.z() * across * across)) * density(h);
  }
  // ωo refracted through a visible normal (pbrt-v3's
  // MicrofacetTransmission::Sample_f); nothing under total internal reflection.
  std::optional<DirectionShading> sample_visible_transmission(DirectionShading wo, Real eta, Real u1, Real u2) const {
    return refract(wo, sample_visible_normal(wo, u1, u2), eta);
  }
  // Its density per solid angle of ωi: the visible normal's density times
  // dω_h/dω_i = η² |ωi·h| / (ωo·h + η ωi·h)².
  PdfSolidAngle visible_transmission_pdf(DirectionShading wo, DirectionShading wi, DirectionShading h, Real eta) const {
    const Real o_h = sg::dot(wo, h), i_h = sg::dot(wi, h);
    if (!(o_h > 0 && i_h < 0)) return sg::zero;
    const Real across = o_h + eta * i_h;
    return visible_normal_pdf(wo, h) * std::abs(eta * eta * i_h / (across * across));
  }

 private:
  Real lambda(DirectionShading w) const {
    const Real cos2 = w.z() * w.z();
    if (!(cos2 > 0)) return 0;
    const Real tan2 = std::max(Real(0), 1 - cos2) / cos2;
    return (std::sqrt(1 + alpha_ * alpha_ * tan2) - 1) / 2;
  }

  Real alpha_;
};

// The half vector of a reflection, on the normal's side.
inline DirectionShading half_vector(DirectionShading wo, DirectionShading wi) {
  return sg::normalize(wo + wi);
}

// The microfacet normal that refracts ωo into ωi on the other side, eta =
// n_far / n_near: pbrt-v3's ωo + η ωi, turned to the normal's side.
inline DirectionShading transmission_half_vector(DirectionShading wo, DirectionShading wi, Real eta) {
  const DirectionShading h = sg::normalize(wo * Real(1) + wi * eta);
  return h.z() < 0 ? -h : h;
}

// dω_h / dω_i for reflection about h: 1 / (4 |ωo·h|). Both measures are solid
// angles (of microfacet normals and of directions), so the ratio is a number.
inline Real reflection_jacobian(DirectionShading wo, DirectionShading h) {
  return 1 / (4 * std::abs(sg::dot(wo, h)));
}

inline PdfSolidAngle TrowbridgeReitz::reflection_pdf(DirectionShading wo, DirectionShading h) const {
  return normal_pdf(h) * reflection_jacobian(wo, h);
}
inline PdfSolidAngle TrowbridgeReitz::visible_reflection_pdf(DirectionShading wo, DirectionShading h) const {
  return visible_normal_pdf(wo, h) * reflection_jacobian(wo, h);
}

}  // namespace safegi::render
