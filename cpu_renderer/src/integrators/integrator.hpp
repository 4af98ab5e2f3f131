// Light transport estimators: direct lighting and path tracing, both with
// next-event estimation and BSDF sampling combined by MIS (power heuristic),
// and photon mapping (camera paths through specular bounces to the first
// other surface: direct light by next-event estimation, the rest from the
// photon map).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>

#include "scene/camera.hpp"
#include "accel/geometry.hpp"
#include "lights/lights.hpp"
#include "integrators/photon_map.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "integrators/sampler.hpp"
#include "textures/surface_texture.hpp"

namespace safegi::render {

// f·cos θ of a surface, or the phase function of a medium: what scatters
// radiance from one direction into another, per solid angle.
using ScatteringDensity = spectrum<dim::pdf_solid_angle>;

// The media on the two sides of a scattering point, `front` the one its normal
// points to (the same medium on both sides of a point inside one).
struct MediaAround {
  int front = -1;
  int back = -1;
};

// Where a path begins: the camera ray, or under direct lighting a branch
// that a specular surface split off (everything before it was specular, so
// emission it finds counts in full and its cone is still the camera's).
struct PathStart {
  TimedRay ray;
  Reflectance throughput{1.0f};
  int depth = 0;
  PixelCone cone;               // the camera ray's cone where the path starts (textures' footprint)
  Real compression = 1;         // the radiance compression by refraction so far (for Russian roulette)
  int medium = -1;              // the one the ray travels in (media only)
  ConeStep step_x{}, step_y{};  // the image's pixel steps across the cone (ConeFootprint)
};

struct RayCounters {
  uint64_t camera = 0;
  uint64_t extension = 0;
  uint64_t shadow = 0;
};

class Integrator {
 public:
  Integrator(const Scene& scene, const Geometry& geometry, const Lights& lights, const RenderSettings& settings)
      : scene_(scene), geometry_(geometry), lights_(lights), direct_only_(settings.integrator == IntegratorType::direct),
        paired_scatter_samples_(direct_only_ && settings.mis && lights.strategy() == LightStrategy::all &&
                                !scene.has_media()),
        max_depth_(settings.max_depth), mis_(settings.mis), light_samples_(settings.light_samples),
        roulette_depth_(settings.russian_roulette ? settings.russian_roulette_depth : std::numeric_limits<int>::max()),
        textures_(scene),
        pixel_cone_(pixel_cone(scene.camera, settings.width, settings.height, settings.spp)),
        camera_rays_(scene.camera, settings.width, settings.height),
        media_(scene.has_media()) {
    if (media_ && settings.integrator == IntegratorType::photon)
      throw std::invalid_argument(
          "the photon integrator does not trace participating media or invisible surfaces: render with \"path\"");
    // The photons are traced once, before any pixel, from a fixed seed.
    if (settings.integrator == IntegratorType::photon)
      photons_ = std::make_unique<PhotonMap>(scene, geometry, lights, textures_, settings, 0);
  }

  // The photon map of the photon integrator; null for the others.
  const PhotonMap* photon_map() const { return photons_.get(); }

  // Radiance arriving at the camera along `camera_ray`.
  // Inlined into the render loop: as a call per camera sample it cost 0.2 % more instructions on the
  // Cornell box (64², 16 spp).
  [[gnu::always_inline]] Radiance radiance(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters) const {
    // MIS bookkeeping exists only in the instantiations for scenes with area
    // lights; the light-sample loop only in those for several light samples;
    // the texture footprint's bookkeeping only in those for scenes with
    // textures; media tracking only in those for scenes with media.
    bool one = light_samples_ == 1 && lights_.strategy() != LightStrategy::all;
    if (photons_)
      return one ? with_textures<true, true, true>(camera_ray, sampler, counters)
                 : with_textures<true, false, true>(camera_ray, sampler, counters);
    if (lights_.has_area_lights())
      return one ? with_textures<true, true, false>(camera_ray, sampler, counters)
                 : with_textures<true, false, false>(camera_ray, sampler, counters);
    return one ? with_textures<false, true, false>(camera_ray, sampler, counters)
               : with_textures<false, false, false>(camera_ray, sampler, counters);
  }

 private:
  template <bool area_lights, bool one_light_sample, bool gather>
  Radiance with_textures(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters) const {
    return textures_.any() ? with_media<area_lights, one_light_sample, gather, true>(camera_ray, sampler, counters)
                           : with_media<area_lights, one_light_sample, gather, false>(camera_ray, sampler, counters);
  }
  template <bool area_lights, bool one_light_sample, bool gather, bool textured>
  Radiance with_media(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters) const {
    PathStart start{.ray = camera_ray, .cone = pixel_cone_, .medium = scene_.camera.medium};
    if constexpr (textured) std::tie(start.step_x, start.step_y) = camera_rays_.pixel_steps(camera_ray.d);
    int splits_left = kMaxSpecularSplits;
    // The photon integrator refuses scenes with media (see the constructor).
    if constexpr (!gather)
      if (media_) return trace<area_lights, one_light_sample, false, textured, true>(start, sampler, counters, splits_left);
    return trace<area_lights, one_light_sample, gather, textured, false>(start, sampler, counters, splits_left);
  }

  // The radiance a path from `start` brings back. gather: the photon
  // integrator's camera pass (see PhotonMap); textured: the scene has
  // textures; media: it has participating media or invisible surfaces.
  // `splits_left`: the branches that direct lighting's specular vertices may
  // still split off, shared by the camera sample's whole tree.
  template <bool area_lights, bool one_light_sample, bool gather, bool textured, bool media>
  Radiance trace(const PathStart& start, Sampler& sampler, RayCounters& counters, int& splits_left) const;

  // Next-event estimation at a point that scatters as `scatter` says (a
  // surface's BSDF or a medium's phase function): light samples, each weighed
  // against `scatter`'s own sampling when `mis`, through shadow rays that start
  // in `from_medium.front` or `from_medium.back` (the side of `from.normal` they leave by).
  template <bool area_lights, bool one_light_sample, bool media, class Scatter>
  Radiance sample_direct(const SurfaceHit& from, const Scatter& scatter, MediaAround from_medium, Sampler& sampler,
                         Time time, bool mis, RayCounters& counters) const;
  // pbrt-v3's directlighting pairs each sample of an area light (or the
  // environment) with a BSDF sample that counts that light's emission alone,
  // both weighed by MIS: the BSDF half of one pair, `count` rounds of samples
  // per shading point.
  template <class Scatter>
  Radiance paired_scatter_sample(uint32_t light, const SurfaceHit& from, const Scatter& scatter, Real count,
                                 Sampler& sampler, Time time, RayCounters& counters) const;
  // What one light sample adds through a scattering density (f·cos θ, or a
  // phase function) that is `scattering` towards it and samples it with `scattering_pdf`.
  template <bool area_lights>
  Radiance light_contribution(const LightSample& light, ScatteringDensity scattering, PdfSolidAngle scattering_pdf,
                              Real light_sample_count, bool mis) const;
  // The fraction of light that gets from `shadow`'s origin to t_max along it:
  // 0 or 1 without media; with them, the media's transmittance, through
  // invisible surfaces (a visible one blocks it). The ray starts in `medium`.
  template <bool media>
  Reflectance visibility(const TimedRay& shadow, Length t_max, int medium, RayCounters& counters) const;

  // Direct lighting follows every lobe of a specular surface (glass's
  // reflection and refraction, as pbrt-v3's directlighting and whitted do), up
  // to this many branches per camera sample; beyond them, in a hall of glass
  // panes whose branches would double at every bounce, one lobe chosen by
  // Fresnel (the path tracer's way, unbiased too). pbrt-v3's default depth, 5,
  // splits at most 31 times.
  static constexpr int kMaxSpecularSplits = 64;

  const Scene& scene_;
  const Geometry& geometry_;
  const Lights& lights_;
  bool direct_only_;
  // Direct lighting with every light sampled (pbrt-v3's directlighting): its
  // BSDF samples are paired with the light samples (paired_scatter_sample),
  // instead of one per shading point collecting every light's emission.
  bool paired_scatter_samples_;
  int max_depth_;
  bool mis_;           // off: emission found by BSDF sampling after a non-specular bounce is dropped
  int light_samples_;  // rounds of next-event samples per shading point (Lights)
  int roulette_depth_;
  SurfaceTextures textures_;
  PixelCone pixel_cone_;
  CameraRays camera_rays_;  // for the pixel steps of the camera's rays
  bool media_;  // the scene has participating media or invisible surfaces
  std::unique_ptr<PhotonMap> photons_;
};

}  // namespace safegi::render
