// Stochastic progressive photon mapping (Hachisuka & Jensen 2009; pbrt-v3's
// SPPMIntegrator). Each iteration traces one camera path per pixel through
// specular bounces to its first non-specular surface, the pixel's visible
// point, adding the emission and direct light found there (Ld); then a pass
// of photons from the lights (chosen by power), each depositing its flux at
// every non-specular surface after its first; every visible point gathers
// the photons within its radius r,
//
//   Φ = Σ_p f(x, ωo, ωp) · Φ_p                  [W · 1/(sr·proj)],
//
// and its statistics shrink the radius (alpha = 2/3), M photons found:
//
//   N' = N + αM,   r'² = r² N' / (N + M),   τ' = (τ + Φ) r'² / r².
//
// The pixel's radiance is L = Ld / iterations + τ / (N_e · π r²), N_e the
// photons emitted in all: f Φ over an area, radiance, which the types check.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/sampling.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

namespace sppm {

// What a visible point gathers: a BRDF times a photon's flux.
using GatheredFlux = decltype(Brdf{} * spectrum<dim::power>{});

// A pixel's progressive statistics.
struct PixelStatistics {
  quantity<dim::area> radius2 = sg::zero;  // r²
  Real n = 0;                              // N, photons accumulated (fractionally)
  GatheredFlux tau;                        // τ
};

// pbrt-v3's update after an iteration in which the pixel's visible point
// found `m` photons that brought `phi`.
inline void update(PixelStatistics& p, Real m, const GatheredFlux& phi, Real alpha = Real(2) / Real(3)) {
  if (m > 0) {
    const Real n_new = p.n + alpha * m;
    const Real shrink = n_new / (p.n + m);
    p.radius2 = p.radius2 * shrink;
    p.tau = (p.tau + phi) * shrink;
    p.n = n_new;
  } else {
    p.tau = p.tau + phi;  // nothing found: no change of radius (phi is zero then)
  }
}

// The indirect radiance of a pixel's statistics after `photons` emitted in all.
inline Radiance indirect(const PixelStatistics& p, double photons) {
  if (!(p.radius2 > sg::zero) || photons <= 0) return Radiance{};
  return p.tau / (static_cast<Real>(photons) * kPi * p.radius2);
}

}  // namespace sppm

// Why SPPM cannot render `scene` (none: it can): participating media or invisible surfaces.
std::optional<std::string> sppm_refusal(const Scene& scene);

// The bytes a render of `pixels` pixels holds beyond the film and the geometry:
// each pixel's visible point and statistics, and an iteration's photon
// deposits (counted at up to 5 per photon, in three copies, and their grid).
uint64_t sppm_bytes(const RenderSettings& settings, uint64_t pixels);

// The whole render under integrator sppm (render() dispatches here): a crop is
// rendered, the pixel filter, time budget and partition are not used (every
// pixel one camera sample per iteration, in a box); throws
// std::invalid_argument for a scene it refuses or a distributed render.
Image render_sppm(const Scene& scene, const RenderOptions& options, RenderStats* stats);

}  // namespace safegi::render
