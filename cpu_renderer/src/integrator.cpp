#include "integrator.hpp"

#include <algorithm>

#include "bsdf.hpp"
#include "sampling.hpp"

namespace safegi::render {

namespace {

// Russian roulette starts after this many bounces (as in the pbrt-v3 reference).
constexpr int kRouletteDepth = 3;

}  // namespace

template <bool area_lights>
Rgb Integrator::sample_direct(const SurfaceHit& hit, const Bsdf& bsdf, const ShadingFrame& frame, Float3 wo,
                              Sampler& sampler, float time, RayCounters& counters) const {
  float u_light = sampler.next_1d();
  Sample2 u_point = sampler.next_2d();
  std::optional<LightSample> light = lights_.sample(hit.position, u_light, u_point.u, u_point.v);
  if (!light) return Rgb(0.0f);
  Float3 wi = frame.to_local(light->wi);
  if (wi.z <= 0) return Rgb(0.0f);
  Rgb f = bsdf.eval(wo, wi);
  if (f.is_black()) return Rgb(0.0f);
  float t_max = 0;
  Ray shadow = spawn_ray_to(hit, light->position, light->position_error, light->normal, time, t_max);
  ++counters.shadow;
  if (geometry_.occluded(shadow, t_max)) return Rgb(0.0f);
  if constexpr (area_lights) {
    if (!light->delta) {
      float weight = power_heuristic(light->pdf, bsdf.pdf(wo, wi));
      return f * light->incident * (wi.z * weight / light->pdf);
    }
  }
  return f * light->incident * (wi.z / light->pdf);
}

template <bool area_lights>
Rgb Integrator::trace(Ray ray, Sampler& sampler, RayCounters& counters) const {
  Rgb radiance(0.0f), throughput(1.0f);
  bool specular_bounce = true;  // emission seen directly counts in full
  float previous_bsdf_pdf = 0;
  Float3 previous_position;
  bool last_vertex = false;
  for (int depth = 0;; ++depth) {
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    if (!hit) break;
    if constexpr (area_lights) {
      Rgb emitted = lights_.emitted(*hit, ray.direction);
      if (!emitted.is_black()) {
        float weight = specular_bounce ? 1.0f : power_heuristic(previous_bsdf_pdf, lights_.pdf(previous_position, *hit));
        radiance += throughput * emitted * weight;
      }
    }
    if (last_vertex || depth >= max_depth_) break;
    const Shape& shape = scene_.shapes[hit->shape];
    if (shape.material < 0) break;
    Bsdf bsdf(scene_.materials[shape.material]);
    // Shade on the side the ray arrives from: materials are two-sided.
    if (dot(hit->normal, ray.direction) > 0) hit->normal = hit->normal * -1.0f;
    ShadingFrame frame(hit->normal);
    Float3 wo = frame.to_local(ray.direction * -1.0f);

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
    throughput *= scattered->f * (scattered->specular ? scattered->wi.z : scattered->wi.z / scattered->pdf);
    if (throughput.is_black()) break;
    specular_bounce = scattered->specular;
    previous_bsdf_pdf = scattered->pdf;
    previous_position = hit->position;
    ray = spawn_ray(*hit, frame.to_world(scattered->wi), ray.time);
    ++counters.extension;
    if (depth >= kRouletteDepth && !last_vertex) {
      float survival = std::min(0.95f, throughput.max_component());
      if (sampler.next_1d() >= survival) break;
      throughput = throughput / survival;
    }
  }
  return radiance;
}

template Rgb Integrator::trace<true>(Ray, Sampler&, RayCounters&) const;
template Rgb Integrator::trace<false>(Ray, Sampler&, RayCounters&) const;

}  // namespace safegi::render
