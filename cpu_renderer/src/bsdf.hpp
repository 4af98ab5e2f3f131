// Materials as BRDFs in the local shading space (normal = +z, on the side the
// light leaves towards): Lambert, energy-conserving Phong, perfect mirror.
#pragma once

#include <cmath>
#include <optional>

#include "safegi/cpu_renderer/scene.hpp"
#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

// The Phong lobe's own frame: its axis is the mirror direction.
struct PhongLobe : space_tag<"phong_lobe"> {};

struct BsdfSample {
  DirectionShading wi;
  Reflectance weight;           // f · cos θ / pdf: what the path throughput is multiplied by
  PdfSolidAngle pdf = sg::zero; // zero for the mirror's delta
  bool specular = false;
};

class Bsdf {
 public:
  explicit Bsdf(const Material& material) : material_(material) {
    if (material.type == Material::Type::phong) {
      Real d = sg::average(material.diffuse), s = sg::average(material.specular);
      specular_probability_ = d + s > 0 ? s / (d + s) : 0.0f;
    }
  }

  bool is_specular() const { return material_.type == Material::Type::mirror; }

  Brdf eval(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() <= 0 || wi.z() <= 0) return Brdf{};
    switch (material_.type) {
      case Material::Type::lambert:
        return lambert(material_.diffuse);
      case Material::Type::phong:
        // Lafortune & Willems' normalisation keeps the lobe's albedo <= specular.
        return lambert(material_.diffuse) +
               material_.specular * ((material_.exponent + 2) * 0.5f * kInversePi * lobe_cosine_power(wo, wi)) /
                   units::steradian / units::proj;
      default:
        return Brdf{};
    }
  }

  PdfSolidAngle pdf(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() <= 0 || wi.z() <= 0) return sg::zero;
    switch (material_.type) {
      case Material::Type::lambert:
        return cosine_pdf(wi);
      case Material::Type::phong: {
        PdfSolidAngle lobe = (material_.exponent + 1) * 0.5f * kInversePi * lobe_cosine_power(wo, wi) / units::steradian;
        return (1 - specular_probability_) * cosine_pdf(wi) + specular_probability_ * lobe;
      }
      default:
        return sg::zero;
    }
  }

  std::optional<BsdfSample> sample(DirectionShading wo, Real u_lobe, Real u1, Real u2) const {
    if (wo.z() <= 0) return std::nullopt;
    switch (material_.type) {
      case Material::Type::mirror:
        return BsdfSample{reflect(wo), material_.specular, sg::zero, true};
      case Material::Type::lambert:
      case Material::Type::phong: {
        DirectionShading wi;
        if (u_lobe < specular_probability_) {
          auto lobe_frame = frame<Shading, PhongLobe>::from_normal(sg::to_normal(reflect(wo)));
          wi = lobe_frame.from_local(from_kernel<direction<PhongLobe>>(sample_cosine_power(u1, u2, material_.exponent)));
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

  const Material& material_;
  Real specular_probability_ = 0;
};

}  // namespace safegi::render
