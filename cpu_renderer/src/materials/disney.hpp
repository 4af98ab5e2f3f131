// pbrt-v3's Disney BSDF (its src/materials/disney.cpp, after Burley's 2012
// and 2015 course notes) for a surface that is not thin, in the local shading
// space (normal = +z, on the side the light leaves towards):
//  - diffuse, weighted by (1 − metallic)(1 − spectrans): Burley's diffuse
//    c/π (1 − Fo/2)(1 − Fi/2), its retro-reflection c/π Rr (Fo + Fi + Fo Fi
//    (Rr − 1)) with Rr = 2 roughness cos²θd, and sheen's sheen·Csheen·F(θd)
//    (F(x) = (1 − x)⁵, Schlick's weight; θd the angle between ωi and the half vector);
//  - specular reflection: an anisotropic Trowbridge–Reitz (GGX) lobe with
//    separable Smith masking, G1(ωo) G1(ωi), weighted by pbrt-v3's
//    DisneyFresnel, (1 − metallic) F_dielectric(η) + metallic Schlick(Cspec0);
//  - clearcoat: ¼ clearcoat · Schlick(0.04) · GTR1 · G(α = 0.25) / (4 cos θo cos θi);
//  - specular transmission (spectrans > 0): Walter et al.'s rough refraction,
//    spectrans·√c · (1 − F_dielectric(η)), through the specular lobe's facets.
// A thin surface (pbrt-v3's "thin") blends Burley's diffuse with the fake
// subsurface lobe (Hanrahan–Krueger's approximation) by flatness, sends
// difftrans/2 of its diffuse light through (Lambert transmission of
// difftrans/2 · c), and refracts through facets of roughness (0.65 η − 0.35)
// roughness with height-correlated masking (pbrt-v3's plain TrowbridgeReitz).
// Sampled as pbrt-v3's BSDF::Sample_f samples it: one of the lobes chosen
// uniformly, its direction drawn as its BxDF draws it (the cosine hemisphere
// for the three diffuse ones, visible normals for the specular lobes, GTR1's
// normals for clearcoat), the pdf the lobes' densities averaged.
#pragma once

#include <optional>

#include "safegi/cpu_renderer/scene.hpp"
#include "materials/scattering.hpp"

namespace safegi::render {

// The Trowbridge–Reitz distribution of roughness αx along the shading
// frame's x and αy along its y, with Smith's separable masking–shadowing
// G1(ωo) G1(ωi) (pbrt-v3's DisneyMicrofacetDistribution) or, not
// `separable`, the height-correlated 1 / (1 + Λ(ωo) + Λ(ωi)) (pbrt-v3's
// TrowbridgeReitzDistribution). D(h) is a density per projected solid angle
// of normals, as TrowbridgeReitz's.
class AnisotropicTrowbridgeReitz {
 public:
  AnisotropicTrowbridgeReitz(Real alpha_x, Real alpha_y, bool separable = true)
      : alpha_x_(alpha_x), alpha_y_(alpha_y), separable_(separable) {}

  quantity<dim::pdf_projected_solid_angle> density(DirectionShading h) const;
  // Smith's masking of one direction, 1 / (1 + Λ(ω)).
  // (Along the surface, cos θ = 0, a direction is masked entirely.)
  Real masking(DirectionShading w) const { return w.z() != 0 ? 1 / (1 + lambda(w)) : Real(0); }
  Real masking_shadowing(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() == 0 || wi.z() == 0) return 0;
    return separable_ ? masking(wo) * masking(wi) : 1 / (1 + lambda(wo) + lambda(wi));
  }
  // A normal that ωo sees (Heitz 2018, stretched by αx, αy): density D(h)
  // G1(ωo) max(0, ωo·h) / cos θo per solid angle of normals.
  DirectionShading sample_visible_normal(DirectionShading wo, Real u1, Real u2) const;
  PdfSolidAngle visible_normal_pdf(DirectionShading wo, DirectionShading h) const;

  // Torrance–Sparrow reflection by facets that reflect everything.
  quantity<dim::brdf> reflection(DirectionShading wo, DirectionShading wi, DirectionShading h) const {
    return masking_shadowing(wo, wi) / (4 * wo.z() * wi.z()) * density(h);
  }
  // Walter et al.'s refraction for radiance (see TrowbridgeReitz::transmission).
  quantity<dim::brdf> transmission(DirectionShading wo, DirectionShading wi, DirectionShading h, Real eta) const;
  PdfSolidAngle visible_transmission_pdf(DirectionShading wo, DirectionShading wi, DirectionShading h, Real eta) const;

  Real alpha_x() const { return alpha_x_; }
  Real alpha_y() const { return alpha_y_; }

 private:
  Real lambda(DirectionShading w) const;

  Real alpha_x_, alpha_y_;
  bool separable_;
};

// Burley's GTR1 ("generalised Trowbridge–Reitz", γ = 1) of the clearcoat:
// D(h) = (α² − 1) / (π ln α² (1 + (α² − 1) cos²θh)), ∫ D cos θh dω = 1.
quantity<dim::pdf_projected_solid_angle> gtr1_density(DirectionShading h, Real alpha);
// A normal drawn with density D(h) cos θh per solid angle of normals.
DirectionShading sample_gtr1_normal(Real alpha, Real u1, Real u2);

// pbrt-v3's DisneyMaterial's BxDFs, in the order it adds them.
enum class DisneyLobe {
  diffuse, fake_subsurface, retro, sheen, specular, clearcoat, transmission, diffuse_transmission
};

// The Disney BSDF at one shading point: the material, its colour there (the
// textured "color"), and the side the light leaves towards.
class DisneyBsdf {
 public:
  DisneyBsdf(const DisneyMaterial& material, const Reflectance& colour, bool from_inside);

  bool transmits() const { return material_.spec_trans > 0 || material_.thin; }
  // f(ωo, ωi); `importance`: for photons' flux, which refraction does not
  // compress (pbrt-v3's TransportMode::Importance multiplies its BTDF by η²).
  Brdf eval(DirectionShading wo, DirectionShading wi, bool importance = false) const;
  // The density of sample_direction per solid angle: the lobes' own, averaged.
  PdfSolidAngle pdf(DirectionShading wo, DirectionShading wi) const;
  // A direction drawn from one lobe chosen uniformly by u_lobe; none where it
  // leaves on the wrong side, or meets total internal reflection.
  std::optional<DirectionShading> sample_direction(DirectionShading wo, Real u_lobe, Real u1, Real u2) const;

  int lobe_count() const { return lobe_count_; }
  DisneyLobe lobe(int i) const { return lobes_[i]; }
  // The interface's index, far side over near side.
  Real eta() const { return eta_; }
  // The specular lobe's (αx, αy): pbrt-v3's max(0.001, roughness² / aspect)
  // and max(0.001, roughness² · aspect), aspect = √(1 − 0.9 anisotropic).
  const AnisotropicTrowbridgeReitz& facets() const { return facets_; }
  // Those the transmission refracts through: the same, or a thin surface's
  // of roughness (0.65 η − 0.35) roughness.
  const AnisotropicTrowbridgeReitz& transmission_facets() const { return material_.thin ? thin_facets_ : facets_; }
  // Its Fresnel factor at cos θ between ωi and the facet's normal.
  Reflectance specular_fresnel(Real cos_h) const;

 private:
  const DisneyMaterial& material_;
  Reflectance colour_;
  Real eta_;
  Real diffuse_weight_;
  Real burley_share_ = 1, fake_subsurface_share_ = 0;  // of the diffuse lobe (thin: by flatness and difftrans)
  Reflectance diffuse_transmittance_{};              // thin: difftrans/2 · c
  Reflectance sheen_colour_;      // sheen · Csheen · diffuse weight
  Reflectance specular_colour_;   // Cspec0: the metallic part's reflectance at normal incidence
  Reflectance transmittance_;     // spectrans · √c
  Real clearcoat_alpha_;          // GTR1's α: lerp(clearcoatgloss, 0.1, 0.001)
  AnisotropicTrowbridgeReitz facets_, thin_facets_;
  DisneyLobe lobes_[8] = {};
  int lobe_count_ = 0;
};

}  // namespace safegi::render
