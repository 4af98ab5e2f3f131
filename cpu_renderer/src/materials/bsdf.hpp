// Materials as BSDFs in the local shading space (normal = +z, on the side the
// light leaves towards): Lambert, energy-conserving Phong, perfect mirror,
// smooth glass (Fresnel reflection and refraction), pbrt's plastic (Lambert
// plus a Fresnel-weighted Trowbridge–Reitz microfacet lobe), rough metal
// (the same lobe weighted by the conductor's Fresnel term), pbrt-v3's
// substrate (Ashikhmin and Shirley's FresnelBlend) and pbrt-v3's translucent
// (Lambert and a rough dielectric interface, reflecting and transmitting);
// pbrt-v3's disney in disney.hpp.
#pragma once

#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include "safegi/cpu_renderer/sampling.hpp"
#include "materials/disney.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "materials/scattering.hpp"

namespace safegi::render {

// The Phong lobe's own frame: its axis is the mirror direction (built from it alone,
// so its azimuth is arbitrary: a normal-frame space).
struct PhongLobe : normal_frame_tag<"phong_lobe"> {};

// What a path carries: radiance (traced from the camera) or importance (from
// the lights: photons). Refraction compresses radiance by 1/η² but not flux.
enum class Transport { radiance, importance };

// pbrt-v3's translucent material's BxDFs, in the order it adds them.
enum class TranslucentLobe { diffuse_reflection, diffuse_transmission, glossy_reflection, glossy_transmission };

struct BsdfSample {
  DirectionShading wi;
  Reflectance weight;            // f · cos θ / pdf: what the path throughput is multiplied by
  PdfSolidAngle pdf = sg::zero;  // zero for the deltas (mirror, glass)
  bool specular = false;
  // The 1/η² of radiance refracted into a denser medium, which `weight`
  // includes; Russian roulette divides it out again (pbrt's etaScale), or it
  // would end paths inside glass for a change of medium, not of energy.
  Real compression = 1;
  // A refraction's far side's index over the near side's (1: a reflection).
  Real eta = 1;
};

// Every lobe of a specular BSDF at once, each with its whole weight (f·cos θ
// over the delta's density): a mirror's one, glass's reflection and refraction
// weighed by Fresnel (what pbrt-v3's SpecularReflect and SpecularTransmit follow).
struct SpecularLobes {
  BsdfSample lobe[2];
  int count = 0;
};

class Bsdf {
 public:
  // `diffuse` is the material's diffuse reflectance at the shading point (its
  // texture already applied; referenced, not copied: it must outlive the
  // Bsdf; ignored by materials without a diffuse part); `from_inside`: the
  // light leaves towards the side the geometric normal points away from
  // (glass and translucent: the inside, so η is 1/ior there).
  Bsdf(const Material& material, const Reflectance& diffuse, bool from_inside)
      : model_(material.model), diffuse_(diffuse), from_inside_(from_inside) {
    std::visit(
        [&](const auto& model) {
          // Substrate has both parts too but picks its strategy half and half, as pbrt-v3 does.
          using Model = std::decay_t<decltype(model)>;
          if constexpr (std::is_same_v<Model, PhongMaterial> || std::is_same_v<Model, PlasticMaterial>) {
            Real d = sg::average(diffuse), s = sg::average(model.specular);
            specular_probability_ = d + s > 0 ? s / (d + s) : 0.0f;
          } else if constexpr (std::is_same_v<Model, TranslucentMaterial>) {
            choose_translucent_lobes(model);
          }
        },
        model_);
  }
  // The material's untextured diffuse value (black without a diffuse part).
  explicit Bsdf(const Material& material) : Bsdf(material, untextured_diffuse(material), false) {}
  // The Bsdf refers to its material: a temporary one would dangle.
  explicit Bsdf(Material&&) = delete;
  Bsdf(Material&&, const Reflectance&, bool) = delete;

  bool is_specular() const { return render::is_specular(model_); }
  // Non-specular light through the surface: eval() and pdf() have values
  // below it (wi.z < 0), which light samples there must ask for.
  bool transmits() const {
    const auto* d = std::get_if<DisneyMaterial>(&model_);
    return std::holds_alternative<TranslucentMaterial>(model_) || (d && (d->spec_trans > 0 || d->thin));
  }

  // `transport`: importance, the adjoint BSDF that light paths see (it differs
  // only where transmission compresses radiance).
  Brdf eval(DirectionShading wo, DirectionShading wi, Transport transport = Transport::radiance) const {
    if (wo.z() <= 0 || wi.z() == 0 || (wi.z() < 0 && !transmits())) return Brdf{};
    return std::visit(Overloaded{[&](const LambertMaterial&) { return lambert(diffuse_); },
                                 [&](const OrenNayarMaterial& m) { return oren_nayar(m, wo, wi); },
                                 [&](const PhongMaterial& m) { return eval_lobed(m, wo, wi); },
                                 [&](const PlasticMaterial& m) { return eval_lobed(m, wo, wi); },
                                 [&](const ConductorMaterial& m) { return conductor(m, wo, wi); },
                                 [&](const SubstrateMaterial& m) { return substrate(m, wo, wi); },
                                 [&](const TranslucentMaterial& m) { return translucent(m, wo, wi, transport); },
                                 [&](const DisneyMaterial& m) { return disney(m).eval(wo, wi, transport == Transport::importance); },
                                 [](const MirrorMaterial&) { return Brdf{}; },
                                 [](const GlassMaterial&) { return Brdf{}; },
                                 [](const BlackMaterial&) { return Brdf{}; }},
                      model_);
  }

  PdfSolidAngle pdf(DirectionShading wo, DirectionShading wi) const {
    if (wo.z() <= 0 || wi.z() == 0 || (wi.z() < 0 && !transmits())) return sg::zero;
    return std::visit(Overloaded{[&](const LambertMaterial&) { return cosine_pdf(wi); },
                                 [&](const OrenNayarMaterial&) { return cosine_pdf(wi); },
                                 [&](const PhongMaterial& m) { return pdf_lobed(m, wo, wi); },
                                 [&](const PlasticMaterial& m) { return pdf_lobed(m, wo, wi); },
                                 [&](const ConductorMaterial& m) { return conductor_pdf(m, wo, wi); },
                                 [&](const SubstrateMaterial& m) { return substrate_pdf(m, wo, wi); },
                                 [&](const TranslucentMaterial& m) { return translucent_pdf(m, wo, wi); },
                                 [&](const DisneyMaterial& m) { return disney(m).pdf(wo, wi); },
                                 [](const MirrorMaterial&) { return PdfSolidAngle(sg::zero); },
                                 [](const GlassMaterial&) { return PdfSolidAngle(sg::zero); },
                                 [](const BlackMaterial&) { return PdfSolidAngle(sg::zero); }},
                      model_);
  }

  std::optional<BsdfSample> sample(DirectionShading wo, Real u_lobe, Real u1, Real u2,
                                   Transport transport = Transport::radiance) const {
    using Sampled = std::optional<BsdfSample>;
    if (wo.z() <= 0) return std::nullopt;
    return std::visit(
        Overloaded{[&](const MirrorMaterial& m) -> Sampled { return BsdfSample{reflect(wo), m.reflectance, sg::zero, true}; },
                   [&](const GlassMaterial& m) -> Sampled { return sample_glass(m, wo, u_lobe, transport); },
                   [&](const LambertMaterial&) {
                     DirectionShading wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
                     return weighted(wi, lambert(diffuse_), cosine_pdf(wi));
                   },
                   [&](const OrenNayarMaterial& m) {  // pbrt-v3's default BxDF::Sample_f: the cosine hemisphere
                     DirectionShading wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
                     return weighted(wi, oren_nayar(m, wo, wi), cosine_pdf(wi));
                   },
                   [&](const PhongMaterial& m) { return sample_lobed(m, wo, u_lobe, u1, u2); },
                   [&](const PlasticMaterial& m) { return sample_lobed(m, wo, u_lobe, u1, u2); },
                   [&](const ConductorMaterial& m) -> Sampled {
                     // The lobe is the whole BSDF: every sample is drawn from it.
                     DirectionShading wi = TrowbridgeReitz(m.alpha).sample_reflection(wo, u1, u2);
                     if (wi.z() <= 0) return std::nullopt;  // before conductor(), which divides by cos θi
                     return weighted(wi, conductor(m, wo, wi), conductor_pdf(m, wo, wi));
                   },
                   [&](const SubstrateMaterial& m) -> Sampled {
                     // pbrt-v3's FresnelBlend::Sample_f: the cosine hemisphere or the
                     // coat's visible normals, reflected, each half the time (u_lobe is
                     // its own number here: pbrt-v3 rescales u[0] instead).
                     DirectionShading wi = u_lobe < 0.5f ? from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2))
                                                         : TrowbridgeReitz(m.alpha).sample_visible_reflection(wo, u1, u2);
                     if (wi.z() <= 0) return std::nullopt;  // before substrate(), which divides by cos θi
                     return weighted(wi, substrate(m, wo, wi), substrate_pdf(m, wo, wi));
                   },
                   [&](const TranslucentMaterial& m) { return sample_translucent(m, wo, u_lobe, u1, u2, transport); },
                   [&](const DisneyMaterial& m) -> Sampled {
                     const DisneyBsdf bsdf = disney(m);
                     std::optional<DirectionShading> wi = bsdf.sample_direction(wo, u_lobe, u1, u2);
                     if (!wi) return std::nullopt;
                     return weighted(*wi, bsdf.eval(wo, *wi, transport == Transport::importance), bsdf.pdf(wo, *wi));
                   },
                   [](const BlackMaterial&) -> Sampled { return std::nullopt; }},
        model_);
  }

  // The specular lobes towards which light from wo can leave (none for the
  // other materials, and none whose weight is black).
  SpecularLobes specular_lobes(DirectionShading wo) const {
    SpecularLobes lobes;
    auto add = [&](const BsdfSample& s) {
      if (!sg::is_black(s.weight)) lobes.lobe[lobes.count++] = s;
    };
    if (wo.z() <= 0) return lobes;
    if (const auto* mirror = std::get_if<MirrorMaterial>(&model_)) {
      add(BsdfSample{reflect(wo), mirror->reflectance, sg::zero, true});
    } else if (const auto* glass = std::get_if<GlassMaterial>(&model_)) {
      const Real eta = glass_eta(*glass);
      const Real reflected = fresnel_dielectric(wo.z(), eta);
      std::optional<DirectionShading> wt = refract(wo, eta);
      if (!wt) {  // total internal reflection (or rounding at the critical angle)
        add(BsdfSample{reflect(wo), glass->reflectance, sg::zero, true});
        return lobes;
      }
      add(BsdfSample{reflect(wo), glass->reflectance * reflected, sg::zero, true});
      const Real compression = 1 / (eta * eta);
      add(BsdfSample{*wt, glass->transmittance * ((1 - reflected) * compression), sg::zero, true, compression, eta});
    }
    return lobes;
  }

 private:
  // The far side's index over the near side's.
  Real glass_eta(const GlassMaterial& glass) const { return from_inside_ ? 1 / glass.ior : glass.ior; }

  static const Reflectance& untextured_diffuse(const Material& material) {
    static const Reflectance kBlack{};
    const TexturedReflectance* diffuse = diffuse_of(material);
    return diffuse ? diffuse->value : kBlack;
  }

  DisneyBsdf disney(const DisneyMaterial& m) const { return DisneyBsdf(m, diffuse_, from_inside_); }

  static DirectionShading reflect(DirectionShading w) { return DirectionShading(-w.x(), -w.y(), w.z()); }

  static Brdf lambert(Reflectance albedo) { return albedo * kInversePi / units::steradian / units::proj; }

  // pbrt-v3's OrenNayar::f, in its form: the azimuths' cosine from the
  // directions' components, sin α and tan β from the larger and smaller θ.
  Brdf oren_nayar(const OrenNayarMaterial& m, DirectionShading wo, DirectionShading wi) const {
    const sg::vec3_rep i = sg::raw(wi), o = sg::raw(wo);
    const Real cos_i = std::abs(i.z), cos_o = std::abs(o.z);
    const Real sin_i = std::sqrt(std::max(Real(0), 1 - cos_i * cos_i)), sin_o = std::sqrt(std::max(Real(0), 1 - cos_o * cos_o));
    Real max_cos = 0;
    if (sin_i > Real(1e-4) && sin_o > Real(1e-4)) {
      auto clamped = [](Real x) { return std::clamp(x, Real(-1), Real(1)); };
      max_cos = std::max(Real(0), clamped(i.x / sin_i) * clamped(o.x / sin_o) + clamped(i.y / sin_i) * clamped(o.y / sin_o));
    }
    const bool incoming_higher = cos_i > cos_o;  // θi < θo
    const Real sin_alpha = incoming_higher ? sin_o : sin_i;
    const Real tan_beta = incoming_higher ? sin_i / cos_i : sin_o / cos_o;
    return lambert(diffuse_) * (m.a + m.b * max_cos * sin_alpha * tan_beta);
  }

  // Cosine-weighted directions: 1/π per projected solid angle, i.e. cos θ/π per solid angle.
  static PdfSolidAngle cosine_pdf(DirectionShading wi) {
    return kInversePi / units::steradian / units::proj * sg::cos_theta(wi);
  }

  // Lambert plus a glossy lobe (Phong, plastic), the lobe chosen with
  // specular_probability_ when sampling.
  template <class Lobed>
  Brdf eval_lobed(const Lobed& material, DirectionShading wo, DirectionShading wi) const {
    return lambert(diffuse_) + lobe(material, wo, wi);
  }
  template <class Lobed>
  PdfSolidAngle pdf_lobed(const Lobed& material, DirectionShading wo, DirectionShading wi) const {
    return (1 - specular_probability_) * cosine_pdf(wi) + specular_probability_ * lobe_pdf(material, wo, wi);
  }
  template <class Lobed>
  std::optional<BsdfSample> sample_lobed(const Lobed& material, DirectionShading wo, Real u_lobe, Real u1,
                                         Real u2) const {
    DirectionShading wi = u_lobe < specular_probability_ ? sample_lobe(material, wo, u1, u2)
                                                         : from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
    if (wi.z() <= 0) return std::nullopt;  // before eval_lobed, whose lobes divide by cos θi
    return weighted(wi, eval_lobed(material, wo, wi), pdf_lobed(material, wo, wi));
  }

  // The sample of a direction `wi` drawn with `density` (the whole strategy's,
  // per solid angle), the BSDF being `value` there: the path's throughput is
  // multiplied by f |cos θ| / pdf. None along the surface or where the density
  // vanishes (the reflecting materials' callers turn away those below it).
  static std::optional<BsdfSample> weighted(DirectionShading wi, Brdf value, PdfSolidAngle density) {
    if (wi.z() == 0 || !(density > sg::zero)) return std::nullopt;
    return BsdfSample{wi, value * sg::abs_cos_theta(wi) / density, density, false};
  }

  // Phong: Lafortune & Willems' normalisation keeps the lobe's albedo <= specular.
  static Brdf lobe(const PhongMaterial& phong, DirectionShading wo, DirectionShading wi) {
    return phong.specular * ((phong.exponent + 2) * 0.5f * kInversePi * lobe_cosine_power(phong, wo, wi)) /
           units::steradian / units::proj;
  }
  static PdfSolidAngle lobe_pdf(const PhongMaterial& phong, DirectionShading wo, DirectionShading wi) {
    return (phong.exponent + 1) * 0.5f * kInversePi * lobe_cosine_power(phong, wo, wi) / units::steradian;
  }
  static DirectionShading sample_lobe(const PhongMaterial& phong, DirectionShading wo, Real u1, Real u2) {
    auto lobe_frame = frame<Shading, PhongLobe>::from_normal(sg::to_normal(reflect(wo)));
    return lobe_frame.from_local(from_kernel<direction<PhongLobe>>(sample_cosine_power(u1, u2, phong.exponent)));
  }
  // cos^n of the angle between wi and the mirror direction of wo.
  static Real lobe_cosine_power(const PhongMaterial& phong, DirectionShading wo, DirectionShading wi) {
    Real cos_alpha = sg::dot(reflect(wo), wi);
    return cos_alpha > 0 ? std::pow(cos_alpha, phong.exponent) : 0.0f;
  }

  // Plastic: ρs · F(ωi·h) · D(h) G / (4 cos θo cos θi), the coating's
  // Torrance–Sparrow lobe; sampled by its normals (D(h) cos θh), reflected.
  Brdf lobe(const PlasticMaterial& plastic, DirectionShading wo, DirectionShading wi) const {
    DirectionShading h = half_vector(wo, wi);
    return plastic.specular * coating_fresnel(plastic, sg::dot(wi, h)) *
           TrowbridgeReitz(plastic.alpha).reflection(wo, wi, h);
  }
  static PdfSolidAngle lobe_pdf(const PlasticMaterial& plastic, DirectionShading wo, DirectionShading wi) {
    return TrowbridgeReitz(plastic.alpha).reflection_pdf(wo, half_vector(wo, wi));
  }
  static DirectionShading sample_lobe(const PlasticMaterial& plastic, DirectionShading wo, Real u1, Real u2) {
    return TrowbridgeReitz(plastic.alpha).sample_reflection(wo, u1, u2);
  }
  // The coating's Fresnel factor at the microfacet: from outside (η = ior), or
  // as pbrt-v3's plastic computes it, with the indices swapped (η = 1/ior) —
  // on the side its normal points to; from the other, pbrt-v3's Fresnel sees
  // a negative cosine and swaps them back.
  Real coating_fresnel(const PlasticMaterial& plastic, Real cos_h) const {
    return fresnel_dielectric(cos_h, plastic.pbrt_v3_fresnel && !from_inside_ ? 1 / plastic.ior : plastic.ior);
  }

  // Metal: F_conductor(ωi·h; η, k) · D(h) G / (4 cos θo cos θi), pbrt-v3's
  // MicrofacetReflection with its FresnelConductor; the same lobe as plastic's
  // but weighted per channel by the metal's Fresnel reflectance and alone.
  static Brdf conductor(const ConductorMaterial& metal, DirectionShading wo, DirectionShading wi) {
    DirectionShading h = half_vector(wo, wi);
    return fresnel_conductor(sg::dot(wi, h), metal.eta, metal.k) * TrowbridgeReitz(metal.alpha).reflection(wo, wi, h);
  }
  static PdfSolidAngle conductor_pdf(const ConductorMaterial& metal, DirectionShading wo, DirectionShading wi) {
    return TrowbridgeReitz(metal.alpha).reflection_pdf(wo, half_vector(wo, wi));
  }

  // Substrate: pbrt-v3's FresnelBlend::f. The base, 28/(23π) ρd (1 − ρs)
  // (1 − (1 − cos θi/2)⁵) (1 − (1 − cos θo/2)⁵), is Lambert's ρd/π times what
  // the coat lets through both ways (28/23 normalises that); the coat, D(h) / (4 |ωi·h|
  // max(cos θi, cos θo)) times Schlick's F(ωi·h) = ρs + (1 − ρs)(1 − ωi·h)⁵,
  // has no masking term: Ashikhmin and Shirley's max() stands for it. The
  // denominators are plain ratios, as in TrowbridgeReitz::reflection.
  Brdf substrate(const SubstrateMaterial& substrate, DirectionShading wo, DirectionShading wi) const {
    auto pow5 = [](Real v) { return (v * v) * (v * v) * v; };
    const Reflectance transmitted = Reflectance(1.0f) - substrate.specular;
    const Brdf base = diffuse_ * transmitted *
                      ((28 / (23 * kPi)) * (1 - pow5(1 - wi.z() / 2)) * (1 - pow5(1 - wo.z() / 2))) /
                      units::steradian / units::proj;
    const DirectionShading h = half_vector(wo, wi);
    const Real cos_h = sg::dot(wi, h);
    const Reflectance schlick = substrate.specular + pow5(1 - cos_h) * transmitted;
    return base + schlick * (TrowbridgeReitz(substrate.alpha).density(h) /
                             (4 * std::abs(cos_h) * std::max(wi.z(), wo.z())));
  }
  // pbrt-v3's FresnelBlend::Pdf, ½ (cos θi/π + p(h)/(4 ωo·h)), with p(h) its
  // TrowbridgeReitzDistribution's Pdf for visible-normal sampling (the
  // default it constructs): D(h) G1(ωo) |ωo·h| / cos θo.
  static PdfSolidAngle substrate_pdf(const SubstrateMaterial& substrate, DirectionShading wo, DirectionShading wi) {
    return 0.5f * (cosine_pdf(wi) + TrowbridgeReitz(substrate.alpha).visible_reflection_pdf(wo, half_vector(wo, wi)));
  }

  // Translucent: pbrt-v3's TranslucentMaterial, its BSDF's lobes those with
  // non-black factors (Kd, Ks, reflect, transmit: each checked alone, as
  // pbrt-v3 does), so a texel of black Kd drops the diffuse lobes there.
  void choose_translucent_lobes(const TranslucentMaterial& m) {
    const bool diffuse = !sg::is_black(diffuse_), glossy = !sg::is_black(m.specular);
    const bool back = !sg::is_black(m.reflect), through = !sg::is_black(m.transmit);
    auto add = [&](bool present, TranslucentLobe lobe) {
      if (present) lobes_[lobe_count_++] = lobe;
    };
    add(diffuse && back, TranslucentLobe::diffuse_reflection);
    add(diffuse && through, TranslucentLobe::diffuse_transmission);
    add(glossy && back, TranslucentLobe::glossy_reflection);
    add(glossy && through, TranslucentLobe::glossy_transmission);
  }
  bool has_lobe(TranslucentLobe lobe) const {
    for (int i = 0; i < lobe_count_; ++i)
      if (lobes_[i] == lobe) return true;
    return false;
  }
  // The interface's index on the far side over the near side's.
  Real translucent_eta(const TranslucentMaterial& m) const { return from_inside_ ? 1 / m.ior : m.ior; }

  // Above the surface reflect·(Kd/π + Ks F(ωi·h) D G / (4 cos θo cos θi)),
  // pbrt-v3's FresnelDielectric reflection; below it transmit·(Kd/π + Ks (1 −
  // F(ωo·h)) times Walter's refraction), times η² for importance, as pbrt-v3's
  // MicrofacetTransmission in TransportMode::Importance.
  Brdf translucent(const TranslucentMaterial& m, DirectionShading wo, DirectionShading wi, Transport transport) const {
    const Real eta = translucent_eta(m);
    const TrowbridgeReitz facets(m.alpha);
    Brdf f{};
    if (wi.z() > 0) {
      f = lambert(diffuse_ * m.reflect);
      if (has_lobe(TranslucentLobe::glossy_reflection)) {
        const DirectionShading h = half_vector(wo, wi);
        f += m.reflect * m.specular * fresnel_dielectric(sg::dot(wi, h), eta) * facets.reflection(wo, wi, h);
      }
      return f;
    }
    f = lambert(diffuse_ * m.transmit);
    if (has_lobe(TranslucentLobe::glossy_transmission)) {
      const DirectionShading h = transmission_half_vector(wo, wi, eta);
      const Real importance = transport == Transport::importance ? eta * eta : Real(1);
      f += m.transmit * m.specular * ((1 - fresnel_dielectric(sg::dot(wo, h), eta)) * importance) *
           facets.transmission(wo, wi, h, eta);
    }
    return f;
  }
  // pbrt-v3's BSDF::Pdf: the lobes' densities averaged (a lobe of the other
  // side has none), since one is chosen uniformly.
  PdfSolidAngle translucent_pdf(const TranslucentMaterial& m, DirectionShading wo, DirectionShading wi) const {
    if (lobe_count_ == 0) return sg::zero;
    const TrowbridgeReitz facets(m.alpha);
    const bool above = wi.z() > 0;
    const DirectionShading h = above ? half_vector(wo, wi) : transmission_half_vector(wo, wi, translucent_eta(m));
    PdfSolidAngle sum = sg::zero;
    for (int i = 0; i < lobe_count_; ++i) {
      switch (lobes_[i]) {
        case TranslucentLobe::diffuse_reflection:
          if (above) sum += cosine_pdf(wi);
          break;
        case TranslucentLobe::diffuse_transmission:
          if (!above) sum += cosine_pdf(-wi);
          break;
        case TranslucentLobe::glossy_reflection:
          if (above) sum += facets.visible_reflection_pdf(wo, h);
          break;
        case TranslucentLobe::glossy_transmission:
          if (!above) sum += facets.visible_transmission_pdf(wo, wi, h, translucent_eta(m));
          break;
      }
    }
    return sum / static_cast<Real>(lobe_count_);
  }
  // pbrt-v3's BSDF::Sample_f: a lobe chosen uniformly by u_lobe, its
  // direction drawn as its BxDF draws it (visible normals for both glossy
  // ones), weighed by the whole f and the averaged pdf.
  std::optional<BsdfSample> sample_translucent(const TranslucentMaterial& m, DirectionShading wo, Real u_lobe, Real u1,
                                               Real u2, Transport transport) const {
    if (lobe_count_ == 0) return std::nullopt;
    const TrowbridgeReitz facets(m.alpha);
    const int chosen = std::min(static_cast<int>(u_lobe * static_cast<Real>(lobe_count_)), lobe_count_ - 1);
    std::optional<DirectionShading> wi;
    switch (lobes_[chosen]) {
      case TranslucentLobe::diffuse_reflection:
        wi = from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
        break;
      case TranslucentLobe::diffuse_transmission:
        wi = -from_kernel<DirectionShading>(sample_cosine_hemisphere(u1, u2));
        break;
      case TranslucentLobe::glossy_reflection:
        wi = facets.sample_visible_reflection(wo, u1, u2);
        if (wi->z() <= 0) return std::nullopt;  // reflected below the surface
        break;
      case TranslucentLobe::glossy_transmission:
        wi = facets.sample_visible_transmission(wo, translucent_eta(m), u1, u2);
        if (!wi || wi->z() >= 0) return std::nullopt;  // totally reflected, or refracted above the surface
        break;
    }
    return weighted(*wi, translucent(m, wo, *wi, transport), translucent_pdf(m, wo, *wi));
  }

  // Reflection by the smooth interface or refraction through it, chosen with
  // the Fresnel probability, so that the weight is the tint alone (and 1/η²
  // for radiance crossing into a denser medium).
  std::optional<BsdfSample> sample_glass(const GlassMaterial& glass, DirectionShading wo, Real u,
                                         Transport transport) const {
    const Real eta = glass_eta(glass);
    const Real reflected = fresnel_dielectric(wo.z(), eta);
    if (u < reflected) return BsdfSample{reflect(wo), glass.reflectance, sg::zero, true};
    std::optional<DirectionShading> wt = refract(wo, eta);
    if (!wt) return BsdfSample{reflect(wo), glass.reflectance, sg::zero, true};  // rounding at the critical angle
    const Real compression = transport == Transport::radiance ? 1 / (eta * eta) : Real(1);
    return BsdfSample{*wt, glass.transmittance * compression, sg::zero, true, compression, eta};
  }

  const MaterialModel& model_;
  const Reflectance& diffuse_;
  bool from_inside_;
  Real specular_probability_ = 0;
  TranslucentLobe lobes_[4] = {};  // translucent: its lobes, lobe_count_ of them
  int lobe_count_ = 0;
};

}  // namespace safegi::render
