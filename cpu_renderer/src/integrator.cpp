#include "integrator.hpp"

#include <algorithm>

#include "bsdf.hpp"
#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

namespace {

// Both densities in one measure, so their ratio is a plain number. With n light
// samples against one BSDF sample, the light strategy's density counts n times
// (Veach's power heuristic with sample counts).
Real mis_weight(PdfSolidAngle chosen, PdfSolidAngle other) { return power_heuristic(sg::raw(chosen), sg::raw(other)); }

}  // namespace

// Next-event estimation: radiance reflected towards wo, averaged over
// light_samples_ light samples.
template <bool area_lights, bool one_light_sample>
Radiance Integrator::sample_direct(const SurfaceHit& hit, const Bsdf& bsdf, const ShadingFrame& frame,
                                   DirectionShading wo, Sampler& sampler, Time time, bool mis, bool bumped,
                                   RayCounters& counters) const {
  Radiance sum;
  const int samples = one_light_sample ? 1 : light_samples_;
  const Real count = static_cast<Real>(samples);
  for (int i = 0; i < samples; ++i) {
    Real u_light = sampler.next_1d();
    Sample2 u_point = sampler.next_2d();
    std::optional<LightSample> light = lights_.sample(hit.position, time, u_light, u_point.u, u_point.v);
    if (!light) continue;
    DirectionShading wi = frame.to_local(light->wi);
    if (wi.z() <= 0) continue;
    if (bumped && sg::dot(hit.normal, light->wi) <= sg::zero) continue;  // the shading hemisphere reaches below the surface
    Brdf f = bsdf.eval(wo, wi);
    if (sg::is_black(f)) continue;
    Length t_max = sg::zero;
    TimedRay shadow = spawn_ray_to(hit, light->position, light->position_error, light->emitter_normal, time, t_max);
    ++counters.shadow;
    if (geometry_.occluded(shadow, t_max)) continue;
    if constexpr (area_lights) {
      if (!light->delta) {
        PdfSolidAngle light_pdf = light->pdf * count;
        Real weight = mis ? mis_weight(light_pdf, bsdf.pdf(wo, wi)) : 1.0f;
        sum += f * light->radiance * sg::cos_theta(wi) * (weight / light_pdf);
        continue;
      }
    }
    if (light->directional) {
      // A distant light's irradiance on the surface: its beam's, times the
      // beam's cross-section per unit of surface (cos θ, a ratio of areas here,
      // not a projected solid angle: hence the explicit cast).
      Real cross_section = sg::dimension_cast<dim::dimensionless>(sg::cos_theta(wi));
      sum += f * light->irradiance * (cross_section / (light->probability * count));
      continue;
    }
    // A point light's irradiance: its intensity times the inverse-square law (per
    // projected area) times the receiver's cosine.
    sum += f * light->intensity * sg::solid_angle_per_projected_area(light->distance) * sg::cos_theta(wi) /
           (light->probability * count);
  }
  return sum;
}

template <bool area_lights, bool one_light_sample, bool gather, bool textured>
Radiance Integrator::trace(TimedRay ray, Sampler& sampler, RayCounters& counters) const {
  Radiance radiance;
  Reflectance throughput(1.0f);
  bool specular_bounce = true;  // emission seen directly counts in full
  PdfSolidAngle previous_bsdf_pdf = sg::zero;
  PointWorld previous_position;
  bool last_vertex = false;
  // The camera ray cone's length so far (textures' footprint), while every bounce was specular.
  Length travelled = sg::zero;
  bool sharp_cone = true;
  // Photon integrator: once a non-specular vertex has occurred, emission found
  // through specular bounces only (a caustic path, L S+ D …) is the photon map's.
  bool after_diffuse = false;
  Real compression = 1;  // the radiance compression by refraction so far (for Russian roulette)
  const Real light_sample_count = static_cast<Real>(one_light_sample ? 1 : light_samples_);
  for (int depth = 0;; ++depth) {
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    if (!hit) {
      if constexpr (area_lights) {
        if (lights_.has_environment()) {
          Radiance sky = lights_.environment_radiance(ray.d);
          if (specular_bounce) {
            if (!(gather && after_diffuse)) radiance += throughput * sky;
          }
          else if (mis_)
            radiance += throughput * sky * mis_weight(previous_bsdf_pdf, lights_.environment_pdf(ray.d) * light_sample_count);
        }
      }
      break;
    }
    if constexpr (area_lights) {
      Radiance emitted = lights_.emitted(*hit, ray.d);
      if (!sg::is_black(emitted)) {
        if (specular_bounce) {
          if (!(gather && after_diffuse)) radiance += throughput * emitted;
        } else if (mis_) {
          PdfSolidAngle light_pdf = lights_.pdf(previous_position, *hit, ray.time) * light_sample_count;
          radiance += throughput * emitted * mis_weight(previous_bsdf_pdf, light_pdf);
        }
      }
    }
    if (last_vertex || depth >= max_depth_) break;
    const Shape& shape = scene_.shapes[hit->shape];
    if (shape.material < 0) break;
    const Material& material = scene_.materials[shape.material];
    Reflectance texel{};  // the textured diffuse reflectance, when there is one (black: no diffuse part)
    const TexturedReflectance* diffuse_part = diffuse_of(material);
    const Reflectance* diffuse = diffuse_part ? &diffuse_part->value : &texel;
    if constexpr (textured) {
      travelled += hit->distance;
      if (diffuse_part && diffuse_part->textured()) {
        // The cone's width across the surface, stretched by its tilt (a plain ratio).
        Real tilt = std::max(std::abs(sg::dot(sg::to_direction(hit->normal), ray.d)), Real(1e-3));
        Length width = sharp_cone ? travelled * (pixel_spread_ / units::radian) / tilt : Length(sg::zero);
        texel = textures_.diffuse(material, *hit, width, ray.time);
        diffuse = &texel;
      }
    }
    // Shade on the side the ray arrives from: materials are two-sided (glass
    // tells the sides apart by the geometric normal, which points out).
    const bool from_inside = sg::dot(hit->normal, ray.d) > sg::zero;
    NormalWorld shading_normal = hit->normal;
    bool bumped = false;
    if constexpr (textured) {
      if (material.bump) {
        shading_normal = textures_.bumped_normal(*material.bump, *hit, ray.time);
        bumped = true;
      }
    }
    hit->normal = from_inside ? -hit->normal : hit->normal;
    Bsdf bsdf(material, *diffuse, from_inside);
    ShadingFrame frame = ShadingFrame::from_normal(from_inside ? -shading_normal : shading_normal);
    DirectionShading wo = frame.to_local(-ray.d);

    // Photon integrator: the caustics arriving at every non-specular vertex.
    if constexpr (gather)
      if (!bsdf.is_specular()) radiance += throughput * photons_->estimate(*hit, frame, bsdf, wo);
    if (!bsdf.is_specular() && !lights_.empty())
      radiance += throughput *
                  sample_direct<area_lights, one_light_sample>(*hit, bsdf, frame, wo, sampler, ray.time, mis_, bumped, counters);

    Real u_lobe = sampler.next_1d();
    Sample2 u_direction = sampler.next_2d();
    std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u_direction.u, u_direction.v);
    if (!scattered) break;
    // A bumped normal can send a reflection below the real surface (or a
    // refraction above it): pbrt-v3 then weighs the sample by the lobes of the
    // side it reaches, which have nothing there.
    if (bumped) {
      const bool reflected_geometrically = sg::dot(hit->normal, frame.from_local(scattered->wi)) > sg::zero;
      const bool reflected_in_shading = (scattered->wi.z() > 0) == (wo.z() > 0);
      if (reflected_geometrically != reflected_in_shading) break;
    }
    // Direct lighting follows mirrors but stops after one diffuse bounce, once
    // the BSDF-sampled ray has collected its (MIS-weighted) emission.
    if (direct_only_ && !scattered->specular) {
      if (!area_lights || !mis_) break;
      last_vertex = true;
    }
    throughput *= scattered->weight;
    compression *= scattered->compression;
    if (sg::is_black(throughput)) break;
    specular_bounce = scattered->specular;
    if constexpr (textured) sharp_cone = sharp_cone && scattered->specular;
    if constexpr (gather) after_diffuse = after_diffuse || !scattered->specular;
    previous_bsdf_pdf = scattered->pdf;
    previous_position = hit->position;
    ray = spawn_ray(*hit, frame.from_local(scattered->wi), ray.time);
    ++counters.extension;
    if (depth >= roulette_depth_ && !last_vertex) {
      Real survival = std::min(Real(0.95), sg::max_component(throughput) / compression);
      if (sampler.next_1d() >= survival) break;
      throughput = throughput / survival;
    }
  }
  return radiance;
}

#define SAFEGI_TRACE(area_lights, one_light_sample, gather)                                                  \
  template Radiance Integrator::trace<area_lights, one_light_sample, gather, false>(TimedRay, Sampler&, RayCounters&) \
      const;                                                                                                    \
  template Radiance Integrator::trace<area_lights, one_light_sample, gather, true>(TimedRay, Sampler&, RayCounters&) \
      const
SAFEGI_TRACE(true, true, false);
SAFEGI_TRACE(true, false, false);
SAFEGI_TRACE(false, true, false);
SAFEGI_TRACE(false, false, false);
SAFEGI_TRACE(true, true, true);
SAFEGI_TRACE(true, false, true);
#undef SAFEGI_TRACE

}  // namespace safegi::render
