// The bidirectional path tracer (Veach 1997; pbrt-v3's BDPTIntegrator): a
// camera subpath and a light subpath per camera sample, joined by every
// connection strategy (s light vertices, t camera vertices): s = 0, the
// camera path finds an emitter; s = 1, a light sample at a camera vertex
// (next-event estimation); t = 1, a light vertex seen by the camera (light
// tracing, splatted onto the film where it lands); and s, t ≥ 2, two
// vertices joined by a shadow ray. The strategies are weighed by the balance
// heuristic over the densities with which each would have made the same path.
//
// Those densities are the measure-theoretic core: each vertex keeps its
// density per unit area (PdfArea) under the subpath that made it (fwd) and
// under the opposite one (rev). A BSDF or a light gives a density per solid
// angle; the Jacobian |cos θ| / r² of the vertex it reaches turns it into one
// per area (pdf_solid_angle_to_area), and only densities per area ever meet
// in a ratio. Forgetting the conversion, or the cosine in it, leaves a
// density per solid angle where one per area is expected: a compile error in
// the checked build (testsuite/compile_fail/cases/bdpt_*.cpp show it).
//
// Throughput is typed by the subpath: a camera path's is a plain ratio (the
// camera's importance over its density is one), a light path's is power
// (emitted radiance over the densities of a point and a direction), so a
// connection's contribution is radiance only when both sides' factors and
// the geometry term (per projected area) are all there.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "accel/geometry.hpp"
#include "integrators/integrator.hpp"
#include "lights/lights.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "integrators/sampler.hpp"
#include "textures/surface_texture.hpp"
#include "film/tile_order.hpp"

namespace safegi::render {

// Why the bidirectional path tracer cannot render `scene` as it is (none: it
// can): participating media, the environment and distant lights, cameras
// other than a pinhole, BSDFs that transmit diffusely.
std::optional<std::string> bdpt_refusal(const Scene& scene);

namespace bdpt {

// A vertex's two densities of its position, per unit area: `fwd` under the
// subpath that made it, `rev` under the opposite one. Zero where there is
// none: next to a specular bounce (a delta over directions) and at a point
// light (a delta over positions).
struct Densities {
  PdfArea fwd = sg::zero;
  PdfArea rev = sg::zero;
  bool delta = false;  // scattered by a specular lobe
};

// The balance heuristic's weight of the strategy that joined `light` (s
// vertices, light[0] on the light) to `camera` (t vertices, camera[0] the
// camera's), both holding the densities as that connection leaves them
// (pbrt-v3's MISWeight, its ScopedAssignments made): 1 / Σ_k p_k / p_s, each
// ratio a product of rev / fwd along the vertices between the strategies.
// Next to a delta, pbrt-v3 puts 1 for a zero density; here the density per
// area left over on one side of a specular chain is kept until the one that
// cancels it on the other side (at most two wait, the chain's two ends), so
// every ratio stays a ratio of densities in one measure.
Real mis_weight(std::span<const Densities> light, std::span<const Densities> camera, bool delta_light);

// A contribution of light tracing: the radiance it adds at a film point (in
// pixels from the image's top left corner), as pbrt-v3's Film::AddSplat
// (into the pixel the point is in, unfiltered).
struct Splat {
  Real x = 0, y = 0;
  Radiance radiance;
};

}  // namespace bdpt

class Bdpt {
 public:
  // Throws std::invalid_argument with bdpt_refusal's reason for a scene it cannot render.
  Bdpt(const Scene& scene, const Geometry& geometry, const Lights& lights, const RenderSettings& settings);

  // The radiance of the strategies that end at the camera ray's pixel (t ≥ 2);
  // those of light tracing (t = 1) land anywhere on the film: appended to `splats`.
  Radiance radiance(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters,
                    std::vector<bdpt::Splat>& splats) const;

  struct Vertex;

 private:
  template <class Weight>
  struct PathVertex;
  using CameraVertex = PathVertex<Reflectance>;
  using LightVertex = PathVertex<spectrum<dim::power>>;

  // Extends a subpath from `path.back()` along `ray`, up to `max_vertices` in all.
  template <class Weight>
  void walk(TimedRay ray, Weight beta, PdfSolidAngle pdf, bool importance, size_t max_vertices,
            std::vector<PathVertex<Weight>>& path, Sampler& sampler, RayCounters& counters) const;
  // A surface vertex where `ray` met `hit`, reached from `previous`.
  bool shade(const SurfaceHit& hit, const TimedRay& ray, Vertex& vertex) const;
  // The density per area with which `from`, reached from `before` (none: `from`
  // is a light or the camera), sends its path on to `to`.
  PdfArea density(const Vertex& from, const Vertex* before, const Vertex& to, Time time) const;
  bool visible(const Vertex& a, const Vertex& b, Time time, RayCounters& counters) const;

  Radiance connect(std::span<const LightVertex> light, std::span<const CameraVertex> camera, Sampler& sampler,
                   Time time, RayCounters& counters, std::vector<bdpt::Splat>& splats) const;
  Real weight(std::span<const LightVertex> light, std::span<const CameraVertex> camera, const Vertex* sampled_light,
              Time time) const;

  const Scene& scene_;
  const Geometry& geometry_;
  const Lights& lights_;
  SurfaceTextures textures_;
  CameraRays camera_;
  int max_depth_;
};

// Light tracing's splats over a render: each tile's in a list of its own,
// added to the image in tile order (TileOrder), so the image does not depend
// on the thread count.
class LightImage {
 public:
  explicit LightImage(const PixelRect& window) : window_(window) {
    sums_.assign(3 * static_cast<size_t>(window.x1 - window.x0) * (window.y1 - window.y0), 0.0);
  }
  void begin_pass(size_t tile_count, int threads) { order_.begin_pass(tile_count, threads, kTilesAheadPerThread); }
  void wait_for_room(size_t index) { order_.wait_for_room(index); }
  void add_in_order(size_t index, std::vector<bdpt::Splat>&& splats) {
    order_.add_in_order(index, std::move(splats), [&](const std::vector<bdpt::Splat>& ready) { add_now(ready); });
  }
  // The window's r, g, b sums (over every light path so far).
  std::vector<double>& sums() { return sums_; }

  static constexpr int kTilesAheadPerThread = 8;
  // Samples per pixel in one pass over the tiles: a tile's splats wait in a
  // list until the tiles before it are in, so a pass of at most this many
  // bounds each list (256 pixels × 16 samples × a light path's vertices).
  static constexpr int kPassSpp = 16;
  // The most the splats of the tiles waiting and being rendered hold, for paths of `max_depth`.
  static uint64_t waiting_bytes(int threads, int max_depth) {
    return static_cast<uint64_t>(std::max(1, threads)) * (kTilesAheadPerThread + 1) * 16 * 16 * kPassSpp *
           (static_cast<uint64_t>(std::max(0, max_depth)) + 1) * sizeof(bdpt::Splat);
  }

 private:
  void add_now(const std::vector<bdpt::Splat>& splats);

  PixelRect window_;
  std::vector<double> sums_;
  TileOrder<std::vector<bdpt::Splat>> order_;
};

}  // namespace safegi::render
