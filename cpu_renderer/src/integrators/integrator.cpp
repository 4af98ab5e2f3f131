#include "integrators/integrator.hpp"

#include <algorithm>

#include "materials/bsdf.hpp"
#include "materials/material_mix.hpp"
#include "media/medium.hpp"
#include "safegi/cpu_renderer/sampling.hpp"
#include "materials/surface_scatter.hpp"

namespace safegi::render {

namespace {

// Both densities in one measure, so their ratio is a plain number. With n light
// samples against one BSDF sample, the light strategy's density counts n times
// (Veach's power heuristic with sample counts).
Real mis_weight(PdfSolidAngle chosen, PdfSolidAngle other) { return power_heuristic(sg::raw(chosen), sg::raw(other)); }

// Invisible boundaries a shadow ray crosses at most (each one is a BVH query).
constexpr int kMaxCrossings = 256;

// A point inside a medium: Henyey–Greenstein's phase function about the
// direction the light was travelling.
struct MediumScatter {
  Real asymmetry;
  DirectionWorld travelling;

  std::optional<ScatteringDensity> towards(DirectionWorld wi) const {
    return ScatteringDensity(henyey_greenstein(asymmetry, travelling, wi));
  }
  PdfSolidAngle pdf(DirectionWorld wi) const { return henyey_greenstein(asymmetry, travelling, wi); }
};

// The radius of curvature of `shape` where a ray meets it, positive where it
// bulges towards the ray (the outside of a sphere); none where it is flat,
// and for meshes, whose curvature the ray cone does not follow.
std::optional<Length> convex_radius(const Shape& shape, bool from_inside) {
  if (shape.type != Shape::Type::sphere) return std::nullopt;
  const Length radius = placed_radius(shape.render_from_object, shape.radius);
  return from_inside ? -radius : radius;
}

// The pixel steps across a cone that a specular surface turns from `incoming`
// to `outgoing`: mirrored with the ray (about the normal that reflects it), or,
// refracted, kept across the new direction.
std::pair<ConeStep, ConeStep> steps_beyond(ConeStep step_x, ConeStep step_y, DirectionWorld incoming,
                                           DirectionWorld outgoing, bool reflected) {
  const sg::vec3_rep d = sg::raw(outgoing), mirror_normal = d - sg::raw(incoming);
  const Real mirror_length = glm::length(mirror_normal);
  auto turned = [&](ConeStep step) {
    const sg::vec3_rep e = sg::raw(step);
    if (reflected && mirror_length > Real(1e-6)) {
      const sg::vec3_rep h = mirror_normal / mirror_length;
      return sg::from_raw<ConeStep>(e - h * (2 * glm::dot(e, h)));
    }
    return sg::from_raw<ConeStep>(e - d * glm::dot(e, d));
  };
  return {turned(step_x), turned(step_y)};
}

}  // namespace

template <bool area_lights>
Radiance Integrator::light_contribution(const LightSample& light, ScatteringDensity scattering,
                                        PdfSolidAngle scattering_pdf, Real count, bool mis) const {
  if constexpr (area_lights) {
    if (!light.delta) {
      PdfSolidAngle light_pdf = light.pdf * count;
      Real weight = mis ? mis_weight(light_pdf, scattering_pdf) : 1.0f;
      return scattering * light.radiance * (weight / light_pdf);
    }
  }
  // A distant light's irradiance on the area that faces its beam (a
  // projected area: the receiver's own cosine is in `scattering`).
  if (light.directional) return scattering * light.irradiance / units::proj / (light.probability * count);
  // A point light's: its intensity times the inverse-square law (per projected area).
  return scattering * light.intensity * sg::solid_angle_per_projected_area(light.distance) / (light.probability * count);
}

template <bool media>
Reflectance Integrator::visibility(const TimedRay& shadow, Length t_max, int medium, RayCounters& counters) const {
  ++counters.shadow;
  if constexpr (!media) {
    return geometry_.occluded(shadow, t_max) ? Reflectance{} : Reflectance(1.0f);
  } else {
    // pbrt-v3's VisibilityTester::Tr: from boundary to boundary, each
    // medium's transmittance over its stretch, until a visible surface.
    const PointWorld target = shadow(t_max);
    TimedRay ray = shadow;
    Reflectance through(1.0f);
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
      std::optional<SurfaceHit> hit = geometry_.intersect(ray);
      const bool blocked = hit && hit->distance < t_max;
      if (medium >= 0) through *= transmittance(scene_.media[medium], blocked ? hit->distance : t_max);
      if (!blocked) return through;
      const Shape& shape = scene_.shapes[hit->shape];
      if (!shape.invisible || shape.occludes_light) return Reflectance{};
      medium = medium_beyond(shape, hit->normal, ray.d, medium);
      ray = spawn_ray(*hit, ray.d, ray.time);
      t_max = sg::dot(target - ray.o, ray.d);
      if (!(t_max > sg::zero)) return through;
    }
    return Reflectance{};  // more boundaries than any scene has: taken as blocked
  }
}

template <bool area_lights, bool one_light_sample, bool media, class Scatter>
Radiance Integrator::sample_direct(const SurfaceHit& from, const Scatter& scatter, MediaAround from_medium,
                                   Sampler& sampler, Time time, bool mis, RayCounters& counters) const {
  Radiance sum;
  const int rounds = one_light_sample ? 1 : light_samples_;
  const Real count = static_cast<Real>(rounds);
  // `scattering_share`: what the BSDF's density is scaled by for the MIS
  // weight, 1 against the BSDF sample of the path (one for all the light
  // samples), the light's share of the round against a paired BSDF sample.
  auto add = [&](const std::optional<LightSample>& light, Real scattering_share) {
    if (!light) return;
    std::optional<ScatteringDensity> scattering = scatter.towards(light->wi);
    if (!scattering) return;
    Length t_max = sg::zero;
    TimedRay shadow = spawn_ray_to(from, light->position, light->position_error, light->emitter_normal, time, t_max);
    const int medium = sg::dot(from.normal, light->wi) >= sg::zero ? from_medium.front : from_medium.back;
    Reflectance through = visibility<media>(shadow, t_max, medium, counters);
    if (sg::is_black(through)) return;
    PdfSolidAngle scattering_pdf =
        area_lights && mis && !light->delta ? scatter.pdf(light->wi) * scattering_share : PdfSolidAngle(sg::zero);
    sum += through * light_contribution<area_lights>(*light, *scattering, scattering_pdf, count, mis);
  };
  for (int i = 0; i < rounds; ++i) {
    if (!one_light_sample && lights_.strategy() == LightStrategy::all) {
      for (uint32_t index = 0; index < lights_.size(); ++index)
        for (int k = 0; k < lights_.samples_of(index); ++k) {
          Real u_within = sampler.next_1d();
          Sample2 u_point = sampler.next_2d();
          const bool paired = area_lights && !media && paired_scatter_samples_ && lights_.has_density(index);
          add(lights_.sample_each(index, from.position, time, u_within, u_point.u, u_point.v),
              paired ? lights_.weight_of(index, from.position) * count : Real(1));
          if (paired) sum += paired_scatter_sample(index, from, scatter, count, sampler, time, counters);
        }
      continue;
    }
    Real u_light = sampler.next_1d();
    Sample2 u_point = sampler.next_2d();
    add(lights_.sample(from.position, time, u_light, u_point.u, u_point.v), 1);
  }
  return sum;
}

template <class Scatter>
Radiance Integrator::paired_scatter_sample(uint32_t light, const SurfaceHit& from, const Scatter& scatter, Real count,
                                           Sampler& sampler, Time time, RayCounters& counters) const {
  Real u_lobe = sampler.next_1d();
  Sample2 u_direction = sampler.next_2d();
  if constexpr (std::is_same_v<Scatter, SurfaceScatter>) {
    // Specular lobes are the path's to follow (as pbrt-v3's SpecularReflect);
    // the others' directions have the density scatter.pdf, as for the light samples' weights.
    std::optional<BsdfSample> scattered = scatter.bsdf.sample(scatter.wo, u_lobe, u_direction.u, u_direction.v);
    if (!scattered || scattered->specular) return {};
    const DirectionWorld wi = scatter.frame.from_local(scattered->wi);
    std::optional<ScatteringDensity> f = scatter.towards(wi);
    if (!f || !lights_.may_be_hit(light, from.position, wi)) return {};
    ++counters.extension;
    const TimedRay ray = spawn_ray(from, wi, time);
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    Radiance emitted;
    PdfSolidAngle light_pdf = sg::zero;
    if (hit) {
      if (lights_.light_at(*hit) != static_cast<int32_t>(light)) return {};
      emitted = lights_.emitted(*hit, wi);
      light_pdf = lights_.pdf(from.position, *hit, time) * count;
    } else {
      if (!lights_.is_environment(light)) return {};
      emitted = lights_.environment_radiance(wi);
      light_pdf = lights_.environment_pdf(from.position, wi) * count;
    }
    // The light's densities count its share of the round; the BSDF's the same, so their ratio is the pair's.
    const Real share = lights_.weight_of(light, from.position) * count;
    const PdfSolidAngle scattering_pdf = scatter.pdf(wi) * share;
    if (!(scattering_pdf > sg::zero)) return {};  // a direction the BSDF's sampling cannot draw (a viewer below the shading hemisphere)
    return *f * emitted * (mis_weight(scattering_pdf, light_pdf) / scattering_pdf);
  } else {
    return {};  // media scatter points are not paired (paired_scatter_samples_ is off with media)
  }
}

template <bool area_lights, bool one_light_sample, bool gather, bool textured, bool media>
Radiance Integrator::trace(const PathStart& start, Sampler& sampler, RayCounters& counters, int& splits_left) const {
  Radiance radiance;
  TimedRay ray = start.ray;
  Reflectance throughput = start.throughput;
  bool specular_bounce = true;  // emission seen directly counts in full
  PdfSolidAngle previous_pdf = sg::zero;  // of the direction the last scattering chose
  PointWorld previous_position;
  bool last_vertex = false;
  // The camera ray cone at the path's last vertex (textures' footprint), while every bounce was specular.
  PixelCone cone = start.cone;
  ConeStep step_x = start.step_x, step_y = start.step_y;
  bool sharp_cone = true;
  // Photon integrator: once a non-specular vertex has occurred, emission found
  // through specular bounces only (a caustic path, L S+ D …) is the photon map's.
  bool after_diffuse = false;
  Real compression = start.compression;
  const Real light_sample_count = static_cast<Real>(one_light_sample ? 1 : light_samples_);
  int medium = start.medium;
  int crossings = 0;  // invisible boundaries crossed (media only)
  // Since the last scattering, the ray crossed an invisible surface that
  // occludes light (Shape::occludes_light): the emission it finds is not the
  // scattering point's (media only).
  bool light_hidden = false;
  const bool lights_paired = paired_scatter_samples_ && !lights_.empty();

  // After a scattering event that chose a non-specular direction: direct
  // lighting follows mirrors but stops after one such event, once the
  // sampled ray has collected its (MIS-weighted) emission. False: the path ends.
  // `paired`: the vertex's light samples had BSDF samples of their own
  // (paired_scatter_sample), which found the lights' emission already.
  auto direct_lighting_goes_on = [&](bool paired) {
    if (!direct_only_) return true;
    if (!area_lights || !mis_ || paired) return false;
    last_vertex = true;
    return true;
  };
  // Russian roulette on a path with `weight` so far, once it is long enough. False: the path ends.
  auto survives_roulette = [&](int depth, Reflectance& weight, Real weight_compression) {
    if (depth < roulette_depth_ || last_vertex) return true;
    Real survival = std::min(Real(0.95), sg::max_component(weight) / weight_compression);
    if (sampler.next_1d() >= survival) return false;
    weight = weight / survival;
    return true;
  };

  for (int depth = start.depth;; ++depth) {
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    if constexpr (media) {
      if (medium >= 0) {
        // pbrt-v3's volpath: a free flight through the medium, which may end
        // before the surface (or the sky) in a scattering event.
        const Medium& participating = scene_.media[medium];
        const Length reach = hit ? hit->distance : sg::from_raw<Length>(std::numeric_limits<Real>::infinity());
        Real u_channel = sampler.next_1d(), u_distance = sampler.next_1d();
        FreeFlight flight = sample_free_flight(participating, reach, u_channel, u_distance);
        throughput *= flight.weight;
        if (sg::is_black(throughput)) break;
        if (flight.scattered_at) {
          if (last_vertex || depth >= max_depth_) break;
          SurfaceHit point;  // no surface: no offset for the rays that leave it
          point.position = ray(*flight.scattered_at);
          point.position_error = Real3{0, 0, 0};
          point.normal = sg::to_normal(ray.d);
          const MediumScatter phase{participating.asymmetry, ray.d};
          if (!lights_.empty())
            radiance += throughput * sample_direct<area_lights, one_light_sample, true>(
                                         point, phase, MediaAround{medium, medium}, sampler, ray.time, mis_, counters);
          Sample2 u_direction = sampler.next_2d();
          DirectionWorld wi = sample_henyey_greenstein(participating.asymmetry, ray.d, u_direction.u, u_direction.v);
          if (!direct_lighting_goes_on(false)) break;
          // The phase function is its own density: the throughput stays.
          specular_bounce = false;
          light_hidden = false;
          if constexpr (textured) sharp_cone = false;
          previous_pdf = phase.pdf(wi);
          previous_position = point.position;
          ray = TimedRay{sg::ray<World>{point.position, wi}, ray.time};
          ++counters.extension;
          if (!survives_roulette(depth, throughput, compression)) break;
          continue;
        }
      }
    }
    if (!hit) {
      if constexpr (area_lights) {
        if (lights_.has_environment()) {
          Radiance sky = lights_.environment_radiance(ray.d);
          if (specular_bounce) {
            if (!(gather && after_diffuse)) radiance += throughput * sky;
          }
          else if (mis_ && !light_hidden)
            radiance += throughput * sky *
                        mis_weight(previous_pdf, lights_.environment_pdf(previous_position, ray.d) * light_sample_count);
        }
      }
      break;
    }
    if constexpr (area_lights) {
      Radiance emitted = lights_.emitted(*hit, ray.d);
      if (!sg::is_black(emitted)) {
        if (specular_bounce) {
          if (!(gather && after_diffuse)) radiance += throughput * emitted;
        } else if (mis_ && !light_hidden) {
          PdfSolidAngle light_pdf = lights_.pdf(previous_position, *hit, ray.time) * light_sample_count;
          radiance += throughput * emitted * mis_weight(previous_pdf, light_pdf);
        }
      }
    }
    const Shape& shape = scene_.shapes[hit->shape];
    if constexpr (textured) cone = cone.after(hit->distance);
    MediaAround around;  // media only
    if constexpr (media) {
      if (shape.invisible) {  // no surface: the ray goes on, into the medium beyond
        if (++crossings > kMaxCrossings) break;
        light_hidden = light_hidden || (shape.occludes_light && !specular_bounce);
        medium = medium_beyond(shape, hit->normal, ray.d, medium);
        ray = spawn_ray(*hit, ray.d, ray.time);
        --depth;
        continue;
      }
      around = {medium_beyond(shape, hit->normal, -ray.d, medium), medium_beyond(shape, hit->normal, ray.d, medium)};
    }
    if (last_vertex || depth >= max_depth_) break;
    if (shape.material < 0) break;
    // The camera cone where it meets the surface: nothing to filter after a non-specular bounce.
    auto footprint = [&] {
      return ConeFootprint{sharp_cone ? sg::abs(cone.width) : Length(sg::zero), ray.d, step_x, step_y};
    };
    const Material* chosen = &scene_.materials[shape.material];
    if (chosen->mix) {
      const MaterialChoice choice =
          choose_material(scene_, textures_, shape.material, *hit, textured ? footprint() : ConeFootprint{.direction = ray.d}, ray.time);
      if (!choice.material) break;
      chosen = choice.material;
      if (choice.weighted) throughput *= choice.weight;
    }
    const Material& material = *chosen;
    Reflectance texel{};  // the textured diffuse reflectance, when there is one (black: no diffuse part)
    const TexturedReflectance* diffuse_part = diffuse_of(material);
    const Reflectance* diffuse = diffuse_part ? &diffuse_part->value : &texel;
    if constexpr (textured) {
      if (diffuse_part && diffuse_part->textured()) {
        texel = textures_.diffuse(material, *hit, footprint(), ray.time);
        diffuse = &texel;
      }
    }
    // Shade on the side the ray arrives from: materials are two-sided (glass
    // tells the sides apart by the geometric normal, which points out).
    const bool from_inside = sg::dot(hit->normal, ray.d) > sg::zero;
    NormalWorld shading_normal = hit->normal;
    bool perturbed = false;
    if constexpr (textured) {
      if (material.bump) {
        shading_normal = textures_.bumped_normal(*material.bump, *hit, ray.time);
        perturbed = true;
      } else if (!scene_.shapes[hit->shape].normals.empty()) {
        shading_normal = textures_.interpolated_normal(*hit, ray.time);  // a smooth mesh
        perturbed = true;
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
      radiance += throughput * sample_direct<area_lights, one_light_sample, media>(
                                   *hit, SurfaceScatter{bsdf, frame, wo, hit->normal, perturbed}, around, sampler, ray.time,
                                   mis_, counters);

    // The path beyond this vertex along `sample`; none where it ends.
    auto beyond = [&](const BsdfSample& sample) __attribute__((always_inline)) -> std::optional<PathStart> {
      const DirectionWorld wi = frame.from_local(sample.wi);
      // A perturbed normal can send a reflection below the real surface (or a
      // refraction above it): pbrt-v3 then weighs the sample by the lobes of the
      // side it reaches, which have nothing there.
      const bool reflected_geometrically = sg::dot(hit->normal, wi) > sg::zero;
      if (perturbed) {
        const bool reflected_in_shading = (sample.wi.z() > 0) == (wo.z() > 0);
        if (reflected_geometrically != reflected_in_shading) return std::nullopt;
      }
      if (!sample.specular && !direct_lighting_goes_on(lights_paired)) return std::nullopt;
      PathStart next{spawn_ray(*hit, wi, ray.time), throughput * sample.weight, depth + 1, cone,
                     compression * sample.compression, medium};
      if constexpr (textured)
        if (sample.specular) {
          const std::optional<Length> radius = convex_radius(shape, from_inside);
          next.cone = sample.wi.z() > 0 ? cone.reflected(radius) : cone.refracted(sample.eta, radius);
          std::tie(next.step_x, next.step_y) = steps_beyond(step_x, step_y, ray.d, wi, sample.wi.z() > 0);
        }
      if (sg::is_black(next.throughput)) return std::nullopt;
      if constexpr (media) next.medium = reflected_geometrically ? around.front : around.back;
      ++counters.extension;
      if (!survives_roulette(depth, next.throughput, next.compression)) return std::nullopt;
      return next;
    };

    // Direct lighting ends at a non-specular vertex whose light samples had
    // BSDF samples of their own, or where no BSDF sample is weighed by MIS: draw none.
    if (direct_only_ && !bsdf.is_specular() && !(area_lights && mis_ && !lights_paired)) break;
    Real u_lobe = sampler.next_1d();
    Sample2 u_direction = sampler.next_2d();
    std::optional<BsdfSample> scattered;
    if (direct_only_ && bsdf.is_specular() && splits_left > 0) {
      // Every lobe but the last as a branch of its own; the path goes on along the last.
      const SpecularLobes lobes = bsdf.specular_lobes(wo);
      for (int i = 0; i + 1 < lobes.count && splits_left > 0; ++i) {
        --splits_left;
        if (std::optional<PathStart> branch = beyond(lobes.lobe[i]))
          radiance += trace<area_lights, one_light_sample, gather, textured, media>(*branch, sampler, counters,
                                                                                   splits_left);
      }
      if (lobes.count > 0) scattered = lobes.lobe[lobes.count - 1];
    } else {
      scattered = bsdf.sample(wo, u_lobe, u_direction.u, u_direction.v);
    }
    if (!scattered) break;
    std::optional<PathStart> next = beyond(*scattered);
    if (!next) break;
    ray = next->ray;
    throughput = next->throughput;
    compression = next->compression;
    if constexpr (media) medium = next->medium;
    specular_bounce = scattered->specular;
    light_hidden = false;
    if constexpr (textured) {
      sharp_cone = sharp_cone && scattered->specular;
      cone = next->cone;
      step_x = next->step_x;
      step_y = next->step_y;
    }
    if constexpr (gather) after_diffuse = after_diffuse || !scattered->specular;
    previous_pdf = scattered->pdf;
    previous_position = hit->position;
  }
  return radiance;
}

#define SAFEGI_TRACE_TEXTURED(area_lights, one_light_sample, gather, media)                                       \
  template Radiance Integrator::trace<area_lights, one_light_sample, gather, false, media>( \
      const PathStart&, Sampler&, RayCounters&, int&) const;                                   \
  template Radiance Integrator::trace<area_lights, one_light_sample, gather, true, media>(  \
      const PathStart&, Sampler&, RayCounters&, int&) const
// Media only without gathering: the photon integrator refuses them.
#define SAFEGI_TRACE(area_lights, one_light_sample)                    \
  SAFEGI_TRACE_TEXTURED(area_lights, one_light_sample, false, false); \
  SAFEGI_TRACE_TEXTURED(area_lights, one_light_sample, false, true)
SAFEGI_TRACE(true, true);
SAFEGI_TRACE(true, false);
SAFEGI_TRACE(false, true);
SAFEGI_TRACE(false, false);
SAFEGI_TRACE_TEXTURED(true, true, true, false);
SAFEGI_TRACE_TEXTURED(true, false, true, false);
#undef SAFEGI_TRACE
#undef SAFEGI_TRACE_TEXTURED

}  // namespace safegi::render
