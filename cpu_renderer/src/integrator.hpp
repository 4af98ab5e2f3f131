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

#include "geometry.hpp"
#include "lights.hpp"
#include "photon_map.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "sampler.hpp"
#include "surface_texture.hpp"

namespace safegi::render {

struct RayCounters {
  uint64_t camera = 0;
  uint64_t extension = 0;
  uint64_t shadow = 0;
};

class Integrator {
 public:
  Integrator(const Scene& scene, const Geometry& geometry, const Lights& lights, const RenderSettings& settings)
      : scene_(scene), geometry_(geometry), lights_(lights), direct_only_(settings.integrator == IntegratorType::direct),
        max_depth_(settings.max_depth), mis_(settings.mis), light_samples_(settings.light_samples),
        roulette_depth_(settings.russian_roulette ? settings.russian_roulette_depth : std::numeric_limits<int>::max()),
        textures_(scene),
        // The angle one pixel subtends at the image centre: the camera ray cone's spread.
        pixel_spread_(2 * sg::tan(0.5f * scene.camera.fov) / static_cast<Real>(std::min(settings.width, settings.height)) *
                      units::radian) {
    // The photons are traced once, before any pixel, from a fixed seed.
    if (settings.integrator == IntegratorType::photon)
      photons_ = std::make_unique<PhotonMap>(scene, geometry, lights, textures_, settings, 0);
  }

  // The photon map of the photon integrator; null for the others.
  const PhotonMap* photon_map() const { return photons_.get(); }

  // Radiance arriving at the camera along `camera_ray`.
  Radiance radiance(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters) const {
    // MIS bookkeeping exists only in the instantiations for scenes with area
    // lights; the light-sample loop only in those for several light samples.
    // The texture footprint's bookkeeping exists only in those for scenes with textures.
    bool one = light_samples_ == 1;
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
    return textures_.any() ? trace<area_lights, one_light_sample, gather, true>(camera_ray, sampler, counters)
                           : trace<area_lights, one_light_sample, gather, false>(camera_ray, sampler, counters);
  }

  // gather: the photon integrator's camera pass (see PhotonMap); textured: the scene has textures.
  template <bool area_lights, bool one_light_sample, bool gather, bool textured>
  Radiance trace(TimedRay ray, Sampler& sampler, RayCounters& counters) const;

  // `mis`: weigh area lights against BSDF sampling (false: light sampling is the only strategy).
  // `bumped`: the frame's normal is a bump map's, not the hit's geometric one
  // (then light from below the geometric surface does not count).
  template <bool area_lights, bool one_light_sample>
  Radiance sample_direct(const SurfaceHit& hit, const class Bsdf& bsdf, const ShadingFrame& frame,
                         DirectionShading wo, Sampler& sampler, Time time, bool mis, bool bumped,
                         RayCounters& counters) const;

  const Scene& scene_;
  const Geometry& geometry_;
  const Lights& lights_;
  bool direct_only_;
  int max_depth_;
  bool mis_;           // off: emission found by BSDF sampling after a non-specular bounce is dropped
  int light_samples_;  // next-event samples per shading point
  int roulette_depth_;
  SurfaceTextures textures_;
  Angle pixel_spread_;
  std::unique_ptr<PhotonMap> photons_;
};

}  // namespace safegi::render
