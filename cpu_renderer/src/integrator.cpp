#include "integrator.hpp"

#include <algorithm>

#include "bsdf.hpp"
#include "sampling.hpp"

namespace safegi::render {

namespace {

// Russian roulette starts after this many bounces (as in the pbrt-v3 reference).
constexpr int kRouletteDepth = 3;

// Both densities in one measure, so their ratio is a plain number.
float mis_weight(PdfSolidAngle chosen, PdfSolidAngle other) { return power_heuristic(sg::raw(chosen), sg::raw(other)); }

}  // namespace

// Next-event estimation: radiance reflected towards wo from one light sample.
template <bool area_lights>
Radiance Integrator::sample_direct(const SurfaceHit& hit, const Bsdf& bsdf, const ShadingFrame& frame,
                                   DirectionShading wo, Sampler& sampler, Time time, RayCounters& counters) const {
  float u_light = sampler.next_1d();
  Sample2 u_point = sampler.next_2d();
  std::optional<LightSample> light = lights_.sample(hit.position, u_light, u_point.u, u_point.v);
  if (!light) return Radiance{};
  DirectionShading wi = frame.to_local(light->wi);
  if (wi.z() <= 0) return Radiance{};
  Brdf f = bsdf.eval(wo, wi);
  if (sg::is_black(f)) return Radiance{};
  Length t_max = sg::zero;
  TimedRay shadow = spawn_ray_to(hit, light->position, light->position_error, light->emitter_normal, time, t_max);
  ++counters.shadow;
  if (geometry_.occluded(shadow, t_max)) return Radiance{};
  if constexpr (area_lights) {
    if (!light->delta) {
      float weight = mis_weight(light->pdf, bsdf.pdf(wo, wi));
      return f * light->radiance * sg::cos_theta(wi) * (weight / light->pdf);
    }
  }
  // A point light's irradiance: its intensity times the solid angle a unit of
  // receiving area subtends from it (cos θ / r², the receiver's cosine).
  return f * light->intensity * solid_angle_per_area(sg::cos_theta(wi), light->distance) / light->probability;
}

template <bool area_lights>
Radiance Integrator::trace(TimedRay ray, Sampler& sampler, RayCounters& counters) const {
  Radiance radiance;
  Reflectance throughput(1.0f);
  bool specular_bounce = true;  // emission seen directly counts in full
  PdfSolidAngle previous_bsdf_pdf = sg::zero;
  PointWorld previous_position;
  bool last_vertex = false;
  for (int depth = 0;; ++depth) {
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    if (!hit) break;
    if constexpr (area_lights) {
      Radiance emitted = lights_.emitted(*hit, ray.d);
      if (!sg::is_black(emitted)) {
        float weight = specular_bounce ? 1.0f : mis_weight(previous_bsdf_pdf, lights_.pdf(previous_position, *hit));
        radiance += throughput * emitted * weight;
      }
    }
    if (last_vertex || depth >= max_depth_) break;
    const Shape& shape = scene_.shapes[hit->shape];
    if (shape.material < 0) break;
    Bsdf bsdf(scene_.materials[shape.material]);
    // Shade on the side the ray arrives from: materials are two-sided.
    hit->normal = sg::face_forward(hit->normal, -ray.d);
    ShadingFrame frame = ShadingFrame::from_normal(hit->normal);
    DirectionShading wo = frame.to_local(-ray.d);

    if (!bsdf.is_specular() && !lights_.empty())
      radiance += throughput * sample_direct<area_lights>(*hit, bsdf, frame, wo, sampler, ray.time, counters);

    float u_lobe = sampler.next_1d();
    Sample2 u_direction = sampler.next_2d();
    std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u_direction.u, u_direction.v);
    if (!scattered) break;
    // Direct lighting follows mirrors but stops after one diffuse bounce, once
    // the BSDF-sampled ray has collected its (MIS-weighted) emission.
    if (direct_only_ && !scattered->specular) {
      if constexpr (!area_lights) break;
      last_vertex = true;
    }
    throughput *= scattered->weight;
    if (sg::is_black(throughput)) break;
    specular_bounce = scattered->specular;
    previous_bsdf_pdf = scattered->pdf;
    previous_position = hit->position;
    ray = spawn_ray(*hit, frame.from_local(scattered->wi), ray.time);
    ++counters.extension;
    if (depth >= kRouletteDepth && !last_vertex) {
      float survival = std::min(0.95f, sg::max_component(throughput));
      if (sampler.next_1d() >= survival) break;
      throughput = throughput / survival;
    }
  }
  return radiance;
}

template Radiance Integrator::trace<true>(TimedRay, Sampler&, RayCounters&) const;
template Radiance Integrator::trace<false>(TimedRay, Sampler&, RayCounters&) const;

}  // namespace safegi::render
