// pbrt-v3's Disney BSDF: see disney.hpp.
#include "materials/disney.hpp"

#include <algorithm>
#include <cmath>

namespace safegi::render {

namespace {

// Schlick's weight (1 − cos θ)⁵, cos θ clamped to [0, 1].
Real schlick_weight(Real cos_theta) {
  const Real m = std::clamp(1 - cos_theta, Real(0), Real(1));
  return (m * m) * (m * m) * m;
}

Reflectance lerp(Real t, const Reflectance& a, const Reflectance& b) { return a * (1 - t) + b * t; }

// pbrt-v3's RGBSpectrum::y(): the luminance of linear sRGB.
Real luminance(const Reflectance& c) {
  const sg::vec3_rep v = sg::raw(c);
  return Real(0.212671) * v.x + Real(0.715160) * v.y + Real(0.072169) * v.z;
}

Reflectance channel_sqrt(const Reflectance& c) { return sg::from_raw<Reflectance>(glm::sqrt(glm::max(sg::raw(c), sg::vec3_rep(0)))); }

// A reflectance spread over the projected hemisphere: the BRDF of value r/π.
Brdf over_pi(const Reflectance& r) { return r * kInversePi / units::steradian / units::proj; }

// Cosine-weighted directions: cos θ/π per solid angle.
PdfSolidAngle cosine_pdf(DirectionShading wi) { return kInversePi / units::steradian / units::proj * sg::cos_theta(wi); }

DirectionShading reflected(DirectionShading wo, DirectionShading h) {
  return sg::from_raw<DirectionShading>(sg::raw(sg::reflect(wo, sg::to_normal(h))));
}

// Smith's G1 of the isotropic GGX of α = 0.25 that masks the clearcoat.
Real clearcoat_masking(Real cos_theta) {
  const Real a2 = Real(0.25) * Real(0.25), c2 = cos_theta * cos_theta;
  return 2 * cos_theta / (cos_theta + std::sqrt(a2 + c2 - a2 * c2));
}

}  // namespace

// ---------------------------------------------------------------------------
// The anisotropic microfacets

quantity<dim::pdf_projected_solid_angle> AnisotropicTrowbridgeReitz::density(DirectionShading h) const {
  if (!(h.z() > 0)) return sg::zero;
  const Real x = h.x() / alpha_x_, y = h.y() / alpha_y_, z = h.z();
  const Real s = x * x + y * y + z * z;
  return 1 / (kPi * alpha_x_ * alpha_y_ * s * s) / units::steradian / units::proj;
}

// Smith's Λ(ω) = (√(1 + α² tan²θ) − 1) / 2, α² = αx² cos²φ + αy² sin²φ.
Real AnisotropicTrowbridgeReitz::lambda(DirectionShading w) const {
  const Real cos2 = w.z() * w.z();
  if (!(cos2 > 0)) return 0;  // (not asked: masking() answers for cos θ = 0)
  const Real x = alpha_x_ * w.x(), y = alpha_y_ * w.y();
  return (std::sqrt(1 + (x * x + y * y) / cos2) - 1) / 2;
}

DirectionShading AnisotropicTrowbridgeReitz::sample_visible_normal(DirectionShading wo, Real u1, Real u2) const {
  return sample_ggx_visible_normal(alpha_x_, alpha_y_, wo, u1, u2);
}

PdfSolidAngle AnisotropicTrowbridgeReitz::visible_normal_pdf(DirectionShading wo, DirectionShading h) const {
  return density(h) * (masking(wo) * std::max(Real(0), sg::dot(wo, h)) / wo.z() * units::proj);
}

quantity<dim::brdf> AnisotropicTrowbridgeReitz::transmission(DirectionShading wo, DirectionShading wi, DirectionShading h,
                                                             Real eta) const {
  const Real o_h = sg::dot(wo, h), i_h = sg::dot(wi, h);
  if (!(o_h > 0 && i_h < 0)) return sg::zero;
  const Real across = o_h + eta * i_h;
  return masking_shadowing(wo, wi) * std::abs(o_h * i_h / (wo.z() * wi.z() * across * across)) * density(h);
}

PdfSolidAngle AnisotropicTrowbridgeReitz::visible_transmission_pdf(DirectionShading wo, DirectionShading wi,
                                                                   DirectionShading h, Real eta) const {
  const Real o_h = sg::dot(wo, h), i_h = sg::dot(wi, h);
  if (!(o_h > 0 && i_h < 0)) return sg::zero;
  const Real across = o_h + eta * i_h;
  return visible_normal_pdf(wo, h) * std::abs(eta * eta * i_h / (across * across));
}

// ---------------------------------------------------------------------------
// The clearcoat's GTR1

quantity<dim::pdf_projected_solid_angle> gtr1_density(DirectionShading h, Real alpha) {
  const Real cos_theta = h.z();
  if (!(cos_theta > 0)) return sg::zero;
  const Real a2 = alpha * alpha;
  return (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * cos_theta * cos_theta)) / units::steradian / units::proj;
}

DirectionShading sample_gtr1_normal(Real alpha, Real u1, Real u2) {
  const Real a2 = alpha * alpha;
  const Real cos_theta = std::sqrt(std::max(Real(0), (1 - std::pow(a2, 1 - u1)) / (1 - a2)));
  const Real sin_theta = std::sqrt(std::max(Real(0), 1 - cos_theta * cos_theta));
  const Real phi = 2 * kPi * u2;
  return DirectionShading(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

// ---------------------------------------------------------------------------
// The BSDF

namespace {

Real aspect_of(const DisneyMaterial& m) { return std::sqrt(1 - Real(0.9) * m.anisotropic); }

// pbrt-v3's alphas of a roughness: max(0.001, r²/aspect) along x, max(0.001, r² aspect) along y.
AnisotropicTrowbridgeReitz facets_of(Real roughness, const DisneyMaterial& m, bool separable) {
  return AnisotropicTrowbridgeReitz(std::max(Real(0.001), roughness * roughness / aspect_of(m)),
                                    std::max(Real(0.001), roughness * roughness * aspect_of(m)), separable);
}

}  // namespace

DisneyBsdf::DisneyBsdf(const DisneyMaterial& material, const Reflectance& colour, bool from_inside)
    : material_(material),
      colour_(sg::from_raw<Reflectance>(glm::max(sg::raw(colour), sg::vec3_rep(0)))),  // pbrt-v3's Clamp()
      eta_(from_inside ? 1 / material.eta : material.eta),
      diffuse_weight_((1 - material.metallic) * (1 - material.spec_trans)),
      clearcoat_alpha_((1 - material.clearcoat_gloss) * Real(0.1) + material.clearcoat_gloss * Real(0.001)),
      facets_(facets_of(material.roughness, material, true)),
      // Burley 2015's figure 15: the roughness scaled by the index.
      thin_facets_(facets_of((Real(0.65) * material.eta - Real(0.35)) * material.roughness, material, false)) {
  const Real lum = luminance(colour_);
  // The colour's hue and saturation alone.
  const Reflectance tint = lum > 0 ? colour_ * (1 / lum) : Reflectance(1.0f);
  sheen_colour_ = lerp(material.sheen_tint, Reflectance(1.0f), tint) * (material.sheen * diffuse_weight_);
  const Real r0 = (material.eta - 1) * (material.eta - 1) / ((material.eta + 1) * (material.eta + 1));
  specular_colour_ = lerp(material.metallic, lerp(material.specular_tint, Reflectance(1.0f), tint) * r0, colour_);
  transmittance_ = channel_sqrt(colour_) * material.spec_trans;
  auto add = [&](bool present, DisneyLobe lobe) {
    if (present) lobes_[lobe_count_++] = lobe;
  };
  if (material.thin) {
    const Real through = material.diff_trans / 2;
    burley_share_ = (1 - material.flatness) * (1 - through);
    fake_subsurface_share_ = material.flatness * (1 - through);
    diffuse_transmittance_ = colour_ * through;
  }
  add(diffuse_weight_ > 0, DisneyLobe::diffuse);
  add(diffuse_weight_ > 0 && material.thin, DisneyLobe::fake_subsurface);
  add(diffuse_weight_ > 0, DisneyLobe::retro);
  add(diffuse_weight_ > 0 && material.sheen > 0, DisneyLobe::sheen);
  add(true, DisneyLobe::specular);
  add(material.clearcoat > 0, DisneyLobe::clearcoat);
  add(material.spec_trans > 0, DisneyLobe::transmission);
  add(material.thin, DisneyLobe::diffuse_transmission);
}

// pbrt-v3's DisneyFresnel: the dielectric's Fresnel reflectance of index η
// (swapped from the inside, as pbrt-v3's FrDielectric swaps it) and Schlick's
// from Cspec0, mixed by metallic. (pbrt-v3 clamps Schlick's cosine at 0, so
// its metallic part reflects everything seen from inside; here it is the same
// from either side.)
Reflectance DisneyBsdf::specular_fresnel(Real cos_h) const {
  const Real w = schlick_weight(std::abs(cos_h));
  const Reflectance schlick = specular_colour_ * (1 - w) + Reflectance(w);
  return Reflectance(fresnel_dielectric(std::abs(cos_h), eta_) * (1 - material_.metallic)) + schlick * material_.metallic;
}

Brdf DisneyBsdf::eval(DirectionShading wo, DirectionShading wi, bool importance) const {
  if (!(wo.z() > 0) || wi.z() == 0) return Brdf{};
  if (wi.z() < 0) {
    if (!transmits()) return Brdf{};
    Brdf f = over_pi(diffuse_transmittance_);
    const DirectionShading h = transmission_half_vector(wo, wi, eta_);
    if (material_.spec_trans > 0 && sg::dot(wo, h) > 0) {  // (no h at all where ωo + η ωi = 0: NaN, not > 0)
      const Real through = (1 - fresnel_dielectric(sg::dot(wo, h), eta_)) * (importance ? eta_ * eta_ : Real(1));
      f += transmittance_ * through * transmission_facets().transmission(wo, wi, h, eta_);
    }
    return f;
  }
  const Real fo = schlick_weight(wo.z()), fi = schlick_weight(wi.z());
  const DirectionShading h = half_vector(wo, wi);
  const Real cos_d = sg::dot(wi, h);
  Brdf f{};
  if (diffuse_weight_ > 0) {
    const Reflectance base = colour_ * diffuse_weight_;
    const Real retro = 2 * material_.roughness * cos_d * cos_d;
    Real shape = burley_share_ * (1 - fo / 2) * (1 - fi / 2) + retro * (fo + fi + fo * fi * (retro - 1));
    if (fake_subsurface_share_ > 0) {
      // Hanrahan–Krueger's flattened retro-reflection, 1.25 keeping the albedo roughly.
      const Real flat90 = cos_d * cos_d * material_.roughness;
      const Real flattened = ((1 - fo) + fo * flat90) * ((1 - fi) + fi * flat90);
      shape += fake_subsurface_share_ * Real(1.25) * (flattened * (1 / (wo.z() + wi.z()) - Real(0.5)) + Real(0.5));
    }
    f += over_pi(base * shape);
    if (material_.sheen > 0) f += sheen_colour_ * schlick_weight(cos_d) / units::steradian / units::proj;
  }
  f += specular_fresnel(cos_d) * facets_.reflection(wo, wi, h);
  if (material_.clearcoat > 0) {
    const Real fresnel = Real(0.04) + Real(0.96) * schlick_weight(sg::dot(wo, h));
    const Real masking = clearcoat_masking(wo.z()) * clearcoat_masking(wi.z());
    const Real weight = material_.clearcoat / 4 * fresnel * masking / (4 * wo.z() * wi.z());
    f += Reflectance(1.0f) * (weight * gtr1_density(h, clearcoat_alpha_));
  }
  return f;
}

PdfSolidAngle DisneyBsdf::pdf(DirectionShading wo, DirectionShading wi) const {
  if (!(wo.z() > 0) || wi.z() == 0 || lobe_count_ == 0) return sg::zero;
  const bool above = wi.z() > 0;
  if (!above && !transmits()) return sg::zero;
  const DirectionShading h = above ? half_vector(wo, wi) : transmission_half_vector(wo, wi, eta_);
  PdfSolidAngle sum = sg::zero;
  for (int i = 0; i < lobe_count_; ++i) {
    switch (lobes_[i]) {
      case DisneyLobe::diffuse:
      case DisneyLobe::fake_subsurface:
      case DisneyLobe::retro:
      case DisneyLobe::sheen:
        if (above) sum += cosine_pdf(wi);
        break;
      case DisneyLobe::diffuse_transmission:
        if (!above) sum += cosine_pdf(-wi);
        break;
      case DisneyLobe::specular:
        if (above) sum += facets_.visible_normal_pdf(wo, h) * reflection_jacobian(wo, h);
        break;
      case DisneyLobe::clearcoat:
        if (above) sum += gtr1_density(h, clearcoat_alpha_) * sg::cos_theta(h) * reflection_jacobian(wo, h);
        break;
      case DisneyLobe::transmission:
        if (!above) sum += transmission_facets().visible_transmission_pdf(wo, wi, h, eta_);
        break;
    }
  }
  return sum / static_cast<Real>(lobe_count_);
}

std::optional<DirectionShading> DisneyBsdf::sample_direction(DirectionShading wo, Real u_lobe, Real u1, Real u2) const {
  if (!(wo.z() > 0) || lobe_count_ == 0) return std::nullopt;
  const int chosen = std::min(static_cast<int>(u_lobe * static_cast<Real>(lobe_count_)), lobe_count_ - 1);
  std::optional<DirectionShading> wi;
  switch (lobes_[chosen]) {
    case DisneyLobe::diffuse:
    case DisneyLobe::fake_subsurface:
    case DisneyLobe::retro:
    case DisneyLobe::sheen:
      wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
      break;
    case DisneyLobe::diffuse_transmission:
      wi = -from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
      if (!(wi->z() < 0)) return std::nullopt;
      return wi;
    case DisneyLobe::specular:
      wi = reflected(wo, facets_.sample_visible_normal(wo, u1, u2));
      break;
    case DisneyLobe::clearcoat:
      wi = reflected(wo, sample_gtr1_normal(clearcoat_alpha_, u1, u2));
      break;
    case DisneyLobe::transmission:
      wi = refract(wo, transmission_facets().sample_visible_normal(wo, u1, u2), eta_);
      if (!wi || !(wi->z() < 0)) return std::nullopt;  // totally reflected, or refracted above the surface
      return wi;
  }
  if (!(wi->z() > 0)) return std::nullopt;  // reflected below the surface
  return wi;
}

}  // namespace safegi::render
