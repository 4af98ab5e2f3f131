// Photon mapping (Jensen 1996; pbrt's photon-mapping integrator), as a
// caustic photon map beside the path tracer: photons carry flux from the
// lights through specular bounces (mirrors, glass) and are stored where they
// first land on a non-specular surface; the radiance a surface reflects from
// them is a density estimate,
//
//   L_r(x, ωo) ≈ Σ_p f(x, ωo, ωp) · Φ_p · K(|x − x_p|),
//
// whose kernel K integrates to one over the disc of radius r, so it is a
// density per unit area: f [1/(sr·proj)] × Φ [W] × K [1/m²] is radiance,
// which the types check. The map holds the caustics (light → specular⁺ →
// diffuse); the camera paths trace everything else and leave out what the
// map has: emission reached from a non-specular vertex through specular
// bounces only.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/geometry.hpp"
#include "lights/lights.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "textures/surface_texture.hpp"

namespace safegi::render {

class Bsdf;

struct Photon {
  PointWorld position;
  DirectionWorld towards_light;  // the direction it arrived from
  NormalWorld normal;            // of the surface it landed on
  spectrum<dim::power> flux;
};

// Jensen's cone filter with k = 1: weight 1 − d/r, normalised over the disc,
// K(d) = 3 (1 − d/r) / (π r²).
inline quantity<dim::pdf_area> cone_kernel(Length distance, Length radius) {
  return 3 * (1 - distance / radius) / (kPi * radius * radius);
}

class PhotonMap {
 public:
  // Traces `settings.photons` photons (deterministically, from `seed`) and
  // stores the caustic ones; radius `settings.photon_radius`, or when zero one
  // chosen so that a disc holds about 64 photons on average over the shapes
  // they landed on.
  PhotonMap(const Scene& scene, const Geometry& geometry, const Lights& lights, const SurfaceTextures& textures,
            const RenderSettings& settings, uint32_t seed);

  // Radiance scattered towards wo at `hit` (its normal facing wo) by the
  // photons within the radius, through `bsdf` in `frame`: those that landed on
  // wo's side, and where the BSDF transmits (translucent) those on the other.
  Radiance estimate(const SurfaceHit& hit, const ShadingFrame& frame, const Bsdf& bsdf, DirectionShading wo) const;

  size_t size() const { return photons_.size(); }
  Length radius() const { return radius_; }
  uint64_t traced_rays() const { return traced_rays_; }

 private:
  void trace(const Scene& scene, const Geometry& geometry, const Lights& lights, const SurfaceTextures& textures,
             const RenderSettings& settings, uint32_t seed, std::vector<bool>& received);
  void build_grid();
  int64_t cell_key(int64_t x, int64_t y, int64_t z) const;

  std::vector<Photon> photons_;
  Length radius_ = sg::zero;
  uint64_t traced_rays_ = 0;
  // A hashed uniform grid of cells one radius wide: photons sorted by bucket.
  Real3 grid_origin_;
  Real cell_size_ = 1;
  std::vector<uint32_t> bucket_start_;  // photons of bucket b: [bucket_start_[b], bucket_start_[b + 1])
};

}  // namespace safegi::render
