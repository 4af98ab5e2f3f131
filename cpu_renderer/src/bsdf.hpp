// Materials as BSDFs in the local shading space (normal = +z, on the side the
// light leaves towards): Lambert, energy-conserving Phong, perfect mirror,
// smooth glass (Fresnel reflection and refraction) and pbrt's plastic
// (Lambert plus a Fresnel-weighted Trowbridge–Reitz microfacet lobe).
#pragma once

#include <cmath>
#include <optional>

#include "safegi/cpu_renderer/sampling.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "scattering.hpp"

namespace safegi::render {

// The Phong lobe's own frame: its axis is the mirror direction.
struct PhongLobe : space_tag<"phong_lobe"> {};

// What a path carries: radiance (traced from the camera) or importance (from
// the lights: photons). Refraction compresses radiance by 1/η² but not flux.
enum class Transport { radiance, importance };

struct BsdfSample {
  DirectionShading wi;
  Reflectance weight;            // f · cos θ / pdf: what the path throughput is multiplied by
  PdfSolidAngle pdf = sg::zero;  // zero for the deltas (mirror, glass)
  bool specular = false;
  // The 1/η² of radiance refracted into a denser medium, which `weight`
  // includes; Russian roulette divides it out again (pbrt's etaScale), or it
  // would end paths inside glass for a change of medium, not of energy.
  Real compression = 1;
};

class Bsdf {
 public:
  // `diffuse` is the material's diffuse reflectance at the shading point (its
  // texture already applied; referenced, not copied: it must outlive the
  // Bsdf); `from_inside`: the light leaves towards the side the geometric
  // normal points away from (glass: the inside, so η is 1/ior there).
  Bsdf(const Material& material, const Reflectance& diffuse, bool from_inside)
      : material_(material), diffuse_(diffuse), from_inside_(from_inside) {
    if (material.type == Material::Type::phong || material.type == Material::Type::plastic) {
      Real d = sg::average(diffuse), s = sg::average(material.specular);
      specular_probability_ = d + s > 0 ? s / (d + s) : 0.0f;
    }
  }
  explicit Bsdf(const Material& material) : Bsdf(material, material.diffuse, false) {}

  bool is_specular() const {
    return material_.type == Material::Type::mirror || material_.type == Material::Type::glass;
  }

  Brdf eval(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() <= 0 || wi.z() <= 0) return Brdf{};
    if (material_.type == Material::Type::lambert) return lambert(diffuse_);  // the common case, before the switch
    switch (material_.type) {
      case Material::Type::phong:
        // Lafortune & Willems' normalisation keeps the lobe's albedo <= specular.
        return lambert(diffuse_) +
               material_.specular * ((material_.exponent + 2) * 0.5f * kInversePi * lobe_cosine_power(wo, wi)) /
                   units::steradian / units::proj;
      case Material::Type::plastic:
        return lambert(diffuse_) + microfacet_reflection(wo, wi);
      default:
        return Brdf{};
    }
  }

  PdfSolidAngle pdf(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() <= 0 || wi.z() <= 0) return sg::zero;
    if (material_.type == Material::Type::lambert) return cosine_pdf(wi);
    switch (material_.type) {
      case Material::Type::phong: {
        PdfSolidAngle lobe = (material_.exponent + 1) * 0.5f * kInversePi * lobe_cosine_power(wo, wi) / units::steradian;
        return (1 - specular_probability_) * cosine_pdf(wi) + specular_probability_ * lobe;
      }
      case Material::Type::plastic:
        return (1 - specular_probability_) * cosine_pdf(wi) + specular_probability_ * microfacet_pdf(wo, wi);
      default:
        return sg::zero;
    }
  }

  std::optional<BsdfSample> sample(DirectionShading wo, Real u_lobe, Real u1, Real u2,
                                   Transport transport = Transport::radiance) const {
    if (wo.z() <= 0) return std::nullopt;
    switch (material_.type) {
      case Material::Type::mirror:
        return BsdfSample{reflect(wo), material_.specular, sg::zero, true};
      case Material::Type::glass:
        return sample_glass(wo, u_lobe, transport);
      case Material::Type::lambert: {
        // The general case below, with eval() and pdf() resolved for Lambert (the same arithmetic).
        DirectionShading wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
        if (wi.z() <= 0) return std::nullopt;
        PdfSolidAngle density = cosine_pdf(wi);
        if (!(density > sg::zero)) return std::nullopt;
        return BsdfSample{wi, lambert(diffuse_) * sg::cos_theta(wi) / density, density, false};
      }
      case Material::Type::phong:
      case Material::Type::plastic: {
        DirectionShading wi;
        if (u_lobe < specular_probability_) {
          if (material_.type == Material::Type::plastic) {
            DirectionShading h = TrowbridgeReitz(material_.alpha).sample_normal(u1, u2);
            wi = sg::from_raw<DirectionShading>(sg::raw(sg::reflect(wo, sg::to_normal(h))));
          } else {
            auto lobe_frame = frame<Shading, PhongLobe>::from_normal(sg::to_normal(reflect(wo)));
            wi = lobe_frame.from_local(from_kernel<direction<PhongLobe>>(sample_cosine_power(u1, u2, material_.exponent)));
          }
        } else {
          wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
        }
        if (wi.z() <= 0) return std::nullopt;
        PdfSolidAngle density = pdf(wo, wi);
        if (!(density > sg::zero)) return std::nullopt;
        return BsdfSample{wi, eval(wo, wi) * sg::cos_theta(wi) / density, density, false};
      }
      default:
        return std::nullopt;
    }
  }

 private:
  static DirectionShading reflect(DirectionShading w) { return DirectionShading(-w.x(), -w.y(), w.z()); }

  static Brdf lambert(Reflectance albedo) { return albedo * kInversePi / units::steradian / units::proj; }

  // Cosine-weighted directions: 1/π per projected solid angle, i.e. cos θ/π per solid angle.
  static PdfSolidAngle cosine_pdf(DirectionShading wi) {
    return kInversePi / units::steradian / units::proj * sg::cos_theta(wi);
  }

  // cos^n of the angle between wi and the mirror direction of wo.
  Real lobe_cosine_power(DirectionShading wo, DirectionShading wi) const {
    Real cos_alpha = sg::dot(reflect(wo), wi);
    return cos_alpha > 0 ? std::pow(cos_alpha, material_.exponent) : 0.0f;
  }

  // Reflection by the smooth interface or refraction through it, chosen with
  // the Fresnel probability, so that the weight is the tint alone (and 1/η²
  // for radiance crossing into a denser medium).
  std::optional<BsdfSample> sample_glass(DirectionShading wo, Real u, Transport transport) const {
    // The far side's index over the near side's.
    const Real eta = from_inside_ ? 1 / material_.ior : material_.ior;
    const Real reflected = fresnel_dielectric(wo.z(), eta);
    if (u < reflected) return BsdfSample{reflect(wo), material_.specular, sg::zero, true};
    std::optional<DirectionShading> wt = refract(wo, eta);
    if (!wt) return BsdfSample{reflect(wo), material_.specular, sg::zero, true};  // rounding at the critical angle
    const Real compression = transport == Transport::radiance ? 1 / (eta * eta) : Real(1);
    return BsdfSample{*wt, material_.transmission * compression, sg::zero, true, compression};
  }

  // The coating's Fresnel factor at the microfacet: from outside (η = ior), or
  // as pbrt-v3's plastic computes it, with the indices swapped (η = 1/ior).
  Real coating_fresnel(Real cos_h) const {
    return fresnel_dielectric(cos_h, material_.pbrt_v3_plastic_fresnel ? 1 / material_.ior : material_.ior);
  }

  // ρs · D(h) G F / (4 cos θo cos θi). The two cosines are the geometric
  // factors of the microfacet derivation, plain ratios here: the projected
  // measure is D's, so the result is a BRDF per projected solid angle.
  Brdf microfacet_reflection(DirectionShading wo, DirectionShading wi) const {
    DirectionShading h = half_vector(wo, wi);
    TrowbridgeReitz microfacets(material_.alpha);
    Real ratio = coating_fresnel(sg::dot(wi, h)) * microfacets.masking_shadowing(wo, wi) / (4 * wo.z() * wi.z());
    return material_.specular * ratio * microfacets.density(h);
  }

  // Normals drawn by D(h) cos θh, reflected: the density per solid angle of wi.
  PdfSolidAngle microfacet_pdf(DirectionShading wo, DirectionShading wi) const {
    DirectionShading h = half_vector(wo, wi);
    return TrowbridgeReitz(material_.alpha).normal_pdf(h) * reflection_jacobian(wo, h);
  }

  const Material& material_;
  const Reflectance& diffuse_;
  bool from_inside_;
  Real specular_probability_ = 0;
};

}  // namespace safegi::render
