// Materials as BRDFs in the local shading frame (z = normal on the side the
// light leaves towards): Lambert, energy-conserving Phong, perfect mirror.
#pragma once

#include <cmath>
#include <optional>

#include "safegi/cpu_renderer/scene.hpp"
#include "sampling.hpp"

namespace safegi::render {

struct BsdfSample {
  Float3 wi;      // local
  Rgb f;          // BRDF value; for the mirror, the reflectance divided by cos(theta_i)
  float pdf = 0;  // solid-angle density; 0 for the mirror's delta
  bool specular = false;
};

class Bsdf {
 public:
  explicit Bsdf(const Material& material) : material_(material) {
    if (material.type == Material::Type::phong) {
      float d = material.diffuse.average(), s = material.specular.average();
      specular_probability_ = d + s > 0 ? s / (d + s) : 0.0f;
    }
  }

  bool is_specular() const { return material_.type == Material::Type::mirror; }

  Rgb eval(Float3 wo, Float3 wi) const {
    if (wo.z <= 0 || wi.z <= 0) return Rgb(0.0f);
    switch (material_.type) {
      case Material::Type::lambert:
        return material_.diffuse * kInversePi;
      case Material::Type::phong: {
        // Lafortune & Willems' normalisation keeps the lobe's albedo <= specular.
        float cos_alpha = dot(reflect(wo), wi);
        float lobe = cos_alpha > 0 ? (material_.exponent + 2) * (0.5f * kInversePi) * std::pow(cos_alpha, material_.exponent)
                                   : 0.0f;
        return material_.diffuse * kInversePi + material_.specular * lobe;
      }
      default:
        return Rgb(0.0f);
    }
  }

  float pdf(Float3 wo, Float3 wi) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    switch (material_.type) {
      case Material::Type::lambert:
        return wi.z * kInversePi;
      case Material::Type::phong: {
        float cos_alpha = dot(reflect(wo), wi);
        float lobe = cos_alpha > 0 ? (material_.exponent + 1) * (0.5f * kInversePi) * std::pow(cos_alpha, material_.exponent)
                                   : 0.0f;
        return (1 - specular_probability_) * wi.z * kInversePi + specular_probability_ * lobe;
      }
      default:
        return 0;
    }
  }

  std::optional<BsdfSample> sample(Float3 wo, float u_lobe, float u1, float u2) const {
    if (wo.z <= 0) return std::nullopt;
    switch (material_.type) {
      case Material::Type::mirror: {
        Float3 wi = reflect(wo);
        return BsdfSample{wi, material_.specular * (1.0f / wi.z), 0.0f, true};
      }
      case Material::Type::lambert:
      case Material::Type::phong: {
        Float3 wi;
        if (u_lobe < specular_probability_) {
          Float3 lobe = sample_cosine_power(u1, u2, material_.exponent);
          wi = ShadingFrame(reflect(wo)).to_world(lobe);
        } else {
          wi = sample_cosine_hemisphere(u1, u2);
        }
        if (wi.z <= 0) return std::nullopt;
        float density = pdf(wo, wi);
        if (!(density > 0)) return std::nullopt;
        return BsdfSample{wi, eval(wo, wi), density, false};
      }
      default:
        return std::nullopt;
    }
  }

 private:
  static Float3 reflect(Float3 w) { return {-w.x, -w.y, w.z}; }

  const Material& material_;
  float specular_probability_ = 0;
};

}  // namespace safegi::render
