#include "integrators/bdpt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/bsdf.hpp"
#include "materials/material_mix.hpp"
#include "materials/surface_scatter.hpp"

namespace safegi::render {

std::optional<std::string> bdpt_refusal(const Scene& scene) {
  if (scene.has_media()) return "the scene has participating media or invisible surfaces";
  if (scene.environment) return "the scene has an environment light";
  if (!scene.distant_lights.empty()) return "the scene has a distant light";
  const Camera& camera = scene.camera;
  if (camera.projection != CameraProjection::perspective) return "the camera is not a perspective one";
  if (camera.lens_radius > sg::zero) return "the camera has a thin lens (only a pinhole is supported)";
  for (const Material& material : scene.materials) {
    // A diffuse transmission's reverse density would need the BSDF seen from
    // its other side, which Bsdf::pdf does not give: its MIS weights would not sum to one.
    if (std::holds_alternative<TranslucentMaterial>(material.model))
      return "material \"" + material.name + "\" transmits diffusely (translucent)";
    if (const auto* disney = std::get_if<DisneyMaterial>(&material.model))
      if (disney->spec_trans > 0 || disney->thin)
        return "material \"" + material.name + "\" transmits diffusely (disney)";
  }
  return std::nullopt;
}

namespace bdpt {

namespace {

// The running ratio p_k / p_s along one subpath: a plain number, and the
// densities per area next to specular chains whose partners lie further on.
class RatioChain {
 public:
  void step(PdfArea rev, PdfArea fwd) {
    const bool has_rev = rev > sg::zero, has_fwd = fwd > sg::zero;
    if (has_rev && has_fwd) {
      ratio_ *= rev / fwd;
    } else if (has_rev) {  // fwd came through a delta: its partner is past the chain
      if (waiting_ < waiting_rev_.size()) waiting_rev_[waiting_++] = rev;
      else broken_ = true;
    } else if (has_fwd) {  // rev comes through a delta
      if (waiting_ > 0) ratio_ *= waiting_rev_[--waiting_] / fwd;
      else ratio_ = 0;  // the other strategies cannot make this vertex
    }
    // Neither: a delta's own step, which the chain's ends account for.
  }
  // The ratio, where every density has met its partner.
  std::optional<Real> settled() const {
    if (waiting_ > 0 || broken_) return std::nullopt;
    return ratio_;
  }

 private:
  Real ratio_ = 1;
  std::array<PdfArea, 2> waiting_rev_{};
  size_t waiting_ = 0;
  bool broken_ = false;
};

}  // namespace

Real mis_weight(std::span<const Densities> light, std::span<const Densities> camera, bool delta_light) {
  const size_t s = light.size(), t = camera.size();
  if (s + t == 2) return 1;
  Real sum = 0;
  RatioChain chain;
  for (size_t i = t - 1; i > 0; --i) {
    chain.step(camera[i].rev, camera[i].fwd);
    if (!camera[i].delta && !camera[i - 1].delta)
      if (std::optional<Real> ratio = chain.settled()) sum += *ratio;
  }
  chain = RatioChain{};
  for (size_t i = s; i-- > 0;) {
    chain.step(light[i].rev, light[i].fwd);
    const bool delta_before = i > 0 ? light[i - 1].delta : delta_light;
    if (!light[i].delta && !delta_before)
      if (std::optional<Real> ratio = chain.settled()) sum += *ratio;
  }
  return 1 / (1 + sum);
}

}  // namespace bdpt

struct Bdpt::Vertex {
  enum class Kind : uint8_t { camera, light, surface } kind = Kind::surface;
  // Position and error box; the normal is the geometric one turned to the
  // side the subpath arrived from (a light's: the emission's side).
  SurfaceHit hit;
  NormalWorld surface_normal;  // the geometric normal as the shape has it (which side emits)
  NormalWorld shading_normal;  // on hit.normal's side
  bool on_surface = false;     // false: the camera's pinhole, a point light
  bool connectible = false;    // a BSDF with a non-specular part
  bool delta_light = false;    // a point or spot light
  bool from_inside = false, perturbed = false;
  int32_t light = -1;          // the light the point is on
  const Material* material = nullptr;  // null: no BSDF (the path ends there)
  Reflectance diffuse{};
  Reflectance mix_weight{1.0f};
  ShadingFrame frame;
  DirectionShading wo;  // towards the subpath's previous vertex
  bdpt::Densities densities;
};

template <class Weight>
struct Bdpt::PathVertex : Bdpt::Vertex {
  Weight beta{};  // throughput up to the vertex (a light's own vertex: unused)
};

namespace {

using Vertex = Bdpt::Vertex;

DirectionWorld towards(const Vertex& from, const Vertex& to) { return sg::normalize(to.hit.position - from.hit.position); }

// A density per solid angle at `from` as one per area at `to`: |cos θ_to| / r².
// A point (the pinhole, a point light) has no density per area: none.
PdfArea to_area(PdfSolidAngle pdf, const Vertex& from, const Vertex& to) {
  if (!to.on_surface) return sg::zero;
  const VectorWorld d = to.hit.position - from.hit.position;
  return sg::pdf_solid_angle_to_area(pdf, sg::length_squared(d), to.hit.normal, sg::normalize(d));
}

SurfaceScatter scatter_at(const Vertex& v, const Bsdf& bsdf, bool importance) {
  return SurfaceScatter{bsdf, v.frame, v.wo, v.hit.normal, v.perturbed,
                        importance ? Transport::importance : Transport::radiance};
}

// pbrt-v3's CorrectShadingNormal: a shading normal makes the BSDF asymmetric;
// light paths carry the factor that restores the adjoint.
Real adjoint_correction(const Vertex& v, DirectionWorld wi) {
  const DirectionWorld wo = v.frame.from_local(v.wo);
  const Proj geometric_wo = sg::abs_dot(v.hit.normal, wo), shading_wi = sg::abs_dot(v.shading_normal, wi);
  if (!(geometric_wo > sg::zero) || !(shading_wi > sg::zero)) return 0;
  return (sg::abs_dot(v.shading_normal, wo) / geometric_wo) * (sg::abs_dot(v.hit.normal, wi) / shading_wi);
}

// f · |cos θ| at `v` towards `w` (per solid angle), as the subpath's transport sees it.
std::optional<ScatteringDensity> scattering(const Vertex& v, DirectionWorld w, bool importance) {
  const Bsdf bsdf(*v.material, v.diffuse, v.from_inside);
  std::optional<ScatteringDensity> f = scatter_at(v, bsdf, importance).towards(w);
  if (!f) return std::nullopt;
  Reflectance weight = v.mix_weight;
  if (importance && v.perturbed) weight = weight * adjoint_correction(v, w);
  return *f * weight;
}

}  // namespace

Bdpt::Bdpt(const Scene& scene, const Geometry& geometry, const Lights& lights, const RenderSettings& settings)
    : scene_(scene), geometry_(geometry), lights_(lights), textures_(scene),
      camera_(scene.camera, settings.width, settings.height), max_depth_(settings.max_depth) {
  if (std::optional<std::string> reason = bdpt_refusal(scene))
    throw std::invalid_argument("the bdpt integrator cannot render this scene: " + *reason + ": render with \"path\"");
  if (lights.strategy() != LightStrategy::power)
    throw std::invalid_argument("the bdpt integrator chooses lights by power");
}

bool Bdpt::shade(const SurfaceHit& hit, const TimedRay& ray, Vertex& vertex) const {
  vertex.kind = Vertex::Kind::surface;
  vertex.on_surface = true;
  vertex.hit = hit;
  vertex.surface_normal = hit.normal;
  vertex.light = lights_.light_at(hit);
  const Shape& shape = scene_.shapes[hit.shape];
  const bool from_inside = sg::dot(hit.normal, ray.d) > sg::zero;
  vertex.hit.normal = from_inside ? -hit.normal : hit.normal;
  vertex.shading_normal = vertex.hit.normal;
  if (shape.material < 0) return false;
  // The textures are read unfiltered: a light path has no pixel footprint.
  const ConeFootprint footprint{.direction = ray.d};
  const Material* chosen = &scene_.materials[shape.material];
  if (chosen->mix) {
    const MaterialChoice choice = choose_material(scene_, textures_, shape.material, hit, footprint, ray.time);
    if (!choice.material) return false;
    chosen = choice.material;
    if (choice.weighted) vertex.mix_weight = choice.weight;
  }
  const TexturedReflectance* diffuse = diffuse_of(*chosen);
  if (diffuse) vertex.diffuse = diffuse->textured() ? textures_.diffuse(*chosen, hit, footprint, ray.time) : diffuse->value;
  NormalWorld shading = hit.normal;
  if (chosen->bump) {
    shading = textures_.bumped_normal(*chosen->bump, hit, ray.time);
    vertex.perturbed = true;
  } else if (!shape.normals.empty()) {
    shading = textures_.interpolated_normal(hit, ray.time);
    vertex.perturbed = true;
  }
  vertex.shading_normal = from_inside ? -shading : shading;
  vertex.frame = ShadingFrame::from_normal(vertex.shading_normal);
  vertex.wo = vertex.frame.to_local(-ray.d);
  vertex.material = chosen;
  vertex.from_inside = from_inside;
  vertex.connectible = !Bsdf(*chosen, vertex.diffuse, from_inside).is_specular();
  return true;
}

template <class Weight>
void Bdpt::walk(TimedRay ray, Weight beta, PdfSolidAngle pdf_fwd, bool importance, size_t max_vertices,
                std::vector<PathVertex<Weight>>& path, Sampler& sampler, RayCounters& counters) const {
  while (path.size() < max_vertices) {
    std::optional<SurfaceHit> hit = geometry_.intersect(ray);
    if (!hit) break;
    PathVertex<Weight> next;
    next.beta = beta;
    const bool scatters = shade(*hit, ray, next);
    next.densities.fwd = to_area(pdf_fwd, path.back(), next);
    path.push_back(next);
    PathVertex<Weight>& v = path.back();
    if (!scatters || path.size() >= max_vertices) break;
    const Bsdf bsdf(*v.material, v.diffuse, v.from_inside);
    const Real u_lobe = sampler.next_1d();
    const Sample2 u = sampler.next_2d();
    std::optional<BsdfSample> sample =
        bsdf.sample(v.wo, u_lobe, u.u, u.v, importance ? Transport::importance : Transport::radiance);
    if (!sample) break;
    const DirectionWorld wi = v.frame.from_local(sample->wi);
    // As the path tracer: a sample whose side the shading and geometric normals disagree on ends the path.
    if (v.perturbed && (sg::dot(v.hit.normal, wi) > sg::zero) != (sample->wi.z() > 0)) break;
    Reflectance factor = sample->weight * v.mix_weight;
    if (importance && v.perturbed) factor = factor * adjoint_correction(v, wi);
    beta = beta * factor;
    if (sg::is_black(beta)) break;
    v.densities.delta = sample->specular;
    pdf_fwd = sample->specular ? PdfSolidAngle(sg::zero) : sample->pdf;
    const PdfSolidAngle pdf_rev = sample->specular ? PdfSolidAngle(sg::zero) : bsdf.pdf(sample->wi, v.wo);
    Vertex& previous = path[path.size() - 2];
    previous.densities.rev = to_area(pdf_rev, v, previous);
    ray = spawn_ray(v.hit, wi, ray.time);
    ++counters.extension;
  }
}

PdfArea Bdpt::density(const Vertex& from, const Vertex* before, const Vertex& to, Time time) const {
  const DirectionWorld w = towards(from, to);
  PdfSolidAngle pdf = sg::zero;
  switch (from.kind) {
    case Vertex::Kind::camera:
      if (std::optional<CameraRays::ImagePoint> seen = camera_.image_point(w)) pdf = seen->pdf;
      break;
    case Vertex::Kind::light:
      pdf = lights_.emission_density(static_cast<uint32_t>(from.light), from.hit, w, time).direction;
      break;
    case Vertex::Kind::surface: {
      if (!before || !from.material) break;
      const Bsdf bsdf(*from.material, from.diffuse, from.from_inside);
      pdf = bsdf.pdf(from.frame.to_local(towards(from, *before)), from.frame.to_local(w));
      break;
    }
  }
  return to_area(pdf, from, to);
}

bool Bdpt::visible(const Vertex& a, const Vertex& b, Time time, RayCounters& counters) const {
  // Leave from a surface where there is one (its error box needs the offset).
  const Vertex& from = a.on_surface ? a : b;
  const Vertex& to = a.on_surface ? b : a;
  Length t_max = sg::zero;
  const Real3 target_normal = to.on_surface ? to_kernel(to.hit.normal) : Real3{0, 0, 0};
  const TimedRay shadow = spawn_ray_to(from.hit, to.hit.position, to.hit.position_error, target_normal, time, t_max);
  ++counters.shadow;
  return !geometry_.occluded(shadow, t_max);
}

Radiance Bdpt::radiance(const TimedRay& camera_ray, Sampler& sampler, RayCounters& counters,
                        std::vector<bdpt::Splat>& splats) const {
  // Per thread, reused across samples: the subpaths' vertices.
  thread_local std::vector<CameraVertex> camera_path;
  thread_local std::vector<LightVertex> light_path;
  camera_path.clear();
  light_path.clear();
  camera_path.reserve(static_cast<size_t>(max_depth_) + 2);
  light_path.reserve(static_cast<size_t>(max_depth_) + 1);

  CameraVertex& eye = camera_path.emplace_back();
  eye.kind = Vertex::Kind::camera;
  eye.hit.position = camera_ray.o;
  eye.hit.position_error = Real3{0, 0, 0};
  eye.beta = Reflectance{1.0f};
  walk(camera_ray, Reflectance{1.0f}, camera_.direction_pdf(camera_ray.d), false, static_cast<size_t>(max_depth_) + 2,
       camera_path, sampler, counters);

  const Real u_light = sampler.next_1d();
  const Sample2 u_position = sampler.next_2d(), u_direction = sampler.next_2d();
  if (std::optional<PhotonEmission> emitted = lights_.sample_emission(camera_ray.time, u_light, u_position.u,
                                                                      u_position.v, u_direction.u, u_direction.v)) {
    LightVertex& source = light_path.emplace_back();
    source.kind = Vertex::Kind::light;
    source.light = static_cast<int32_t>(emitted->light);
    source.delta_light = lights_.is_point(emitted->light);
    source.on_surface = !source.delta_light;
    source.hit.position = emitted->origin;
    source.hit.position_error = emitted->origin_error;
    source.hit.normal = from_kernel<NormalWorld>(emitted->surface_normal);
    source.surface_normal = source.hit.normal;
    source.densities.fwd = emitted->choice * emitted->pdf_position;
    const Real3 origin = kernel::offset_ray_origin(to_kernel(emitted->origin), emitted->origin_error,
                                                   emitted->surface_normal, to_kernel(emitted->direction));
    const TimedRay ray{sg::ray<World>{from_kernel<PointWorld>(origin), emitted->direction}, camera_ray.time};
    ++counters.extension;
    walk(ray, emitted->flux, emitted->pdf_direction, true, static_cast<size_t>(max_depth_) + 1, light_path, sampler,
         counters);
  }
  return connect(light_path, camera_path, sampler, camera_ray.time, counters, splats);
}

Radiance Bdpt::connect(std::span<const LightVertex> light, std::span<const CameraVertex> camera, Sampler& sampler,
                       Time time, RayCounters& counters, std::vector<bdpt::Splat>& splats) const {
  Radiance sum;
  for (size_t t = 1; t <= camera.size(); ++t) {
    // s = 1 samples its own light point: it runs whether or not the light
    // subpath started (a spot light's uniform directions miss its cone).
    for (size_t s = 0; s <= std::max<size_t>(light.size(), 1); ++s) {
      const int depth = static_cast<int>(s + t) - 2;
      if ((s == 1 && t == 1) || depth < 0 || depth > max_depth_) continue;
      const CameraVertex& pt = camera[t - 1];
      if (s == 0) {  // the camera path found an emitter
        if (pt.light < 0) continue;
        SurfaceHit emitter = pt.hit;
        emitter.normal = pt.surface_normal;
        const Radiance emitted = lights_.emitted(emitter, towards(camera[t - 2], pt));
        if (sg::is_black(emitted)) continue;
        sum += pt.beta * emitted * weight({}, camera.first(t), nullptr, time);
      } else if (t == 1) {  // light tracing: a light vertex seen through the pinhole
        const LightVertex& qs = light[s - 1];
        if (!qs.connectible) continue;
        const DirectionWorld to_camera = towards(qs, camera[0]);
        const std::optional<CameraRays::ImagePoint> seen = camera_.image_point(-to_camera);
        if (!seen) continue;
        const std::optional<ScatteringDensity> f = scattering(qs, to_camera, true);
        if (!f || !visible(qs, camera[0], time, counters)) continue;
        // The camera's density of the direction, at the distance per projected area: radiance.
        const Radiance contribution = qs.beta * *f * seen->pdf *
                                      sg::solid_angle_per_projected_area(sg::distance(qs.hit.position, camera[0].hit.position));
        splats.push_back({seen->x, seen->y, contribution * weight(light.first(s), camera.first(1), nullptr, time)});
      } else if (s == 1) {  // a light sample at the camera vertex
        if (!pt.connectible) continue;
        const Real u_light = sampler.next_1d();
        const Sample2 u_point = sampler.next_2d();
        const std::optional<LightSample> sample = lights_.sample(pt.hit.position, time, u_light, u_point.u, u_point.v);
        if (!sample) continue;
        const std::optional<ScatteringDensity> f = scattering(pt, sample->wi, false);
        if (!f) continue;
        Vertex source;
        source.kind = Vertex::Kind::light;
        source.light = static_cast<int32_t>(sample->light);
        source.delta_light = sample->delta;
        source.on_surface = !sample->delta;
        source.hit.position = sample->position;
        source.hit.position_error = sample->position_error;
        source.hit.normal = from_kernel<NormalWorld>(sample->emitter_normal);
        source.surface_normal = source.hit.normal;
        if (!visible(pt, source, time, counters)) continue;
        const EmissionDensity origin = lights_.emission_density(sample->light, source.hit, -sample->wi, time);
        source.densities.fwd = origin.choice * origin.position;
        // A point light's intensity at the distance per projected area, or an area light's radiance over its density.
        const Radiance contribution =
            sample->delta
                ? pt.beta * *f * sample->intensity * sg::solid_angle_per_projected_area(sample->distance) / sample->probability
                : pt.beta * *f * sample->radiance / sample->pdf;
        sum += contribution * weight({}, camera.first(t), &source, time);
      } else {  // two subpath vertices joined
        const LightVertex& qs = light[s - 1];
        if (!qs.connectible || !pt.connectible) continue;
        const DirectionWorld w = towards(pt, qs);
        const std::optional<ScatteringDensity> f_camera = scattering(pt, w, false);
        if (!f_camera) continue;
        const std::optional<ScatteringDensity> f_light = scattering(qs, -w, true);
        if (!f_light || !visible(pt, qs, time, counters)) continue;
        const Radiance contribution = qs.beta * *f_light * *f_camera * pt.beta *
                                      sg::solid_angle_per_projected_area(sg::distance(qs.hit.position, pt.hit.position));
        sum += contribution * weight(light.first(s), camera.first(t), nullptr, time);
      }
    }
  }
  return sum;
}

// pbrt-v3's MISWeight: the subpaths' densities as this connection leaves
// them (the two joined vertices' and their predecessors' rev), then the ratios.
// `sampled_light`: s = 1's light sample, in place of light[0].
Real Bdpt::weight(std::span<const LightVertex> light, std::span<const CameraVertex> camera, const Vertex* sampled_light,
                  Time time) const {
  const size_t s = sampled_light ? 1 : light.size(), t = camera.size();
  if (s + t == 2) return 1;
  thread_local std::vector<bdpt::Densities> light_densities, camera_densities;
  light_densities.clear();
  camera_densities.clear();
  for (const LightVertex& v : light) light_densities.push_back(v.densities);
  if (sampled_light) light_densities.assign(1, sampled_light->densities);
  for (const CameraVertex& v : camera) camera_densities.push_back(v.densities);

  const Vertex* qs = s > 0 ? (sampled_light ? sampled_light : &light[s - 1]) : nullptr;
  const Vertex* qs_minus = s > 1 ? &light[s - 2] : nullptr;
  const Vertex& pt = camera[t - 1];
  const Vertex* pt_minus = t > 1 ? &camera[t - 2] : nullptr;
  const bool delta_light = sampled_light ? sampled_light->delta_light : (!light.empty() && light[0].delta_light);

  bdpt::Densities& pt_d = camera_densities[t - 1];
  if (qs) {
    pt_d.rev = density(*qs, qs_minus, pt, time);
  } else {
    // The emitter the camera path found, as a light subpath would have started there.
    SurfaceHit emitter = pt.hit;
    emitter.normal = pt.surface_normal;
    const DirectionWorld out = pt_minus ? towards(pt, *pt_minus) : DirectionWorld{0, 0, 1};
    const EmissionDensity origin = lights_.emission_density(static_cast<uint32_t>(pt.light), emitter, out, time);
    pt_d.rev = origin.choice * origin.position;
  }
  pt_d.delta = false;
  if (pt_minus) {
    if (qs) {
      camera_densities[t - 2].rev = density(pt, qs, *pt_minus, time);
    } else {
      Vertex as_light = pt;
      as_light.kind = Vertex::Kind::light;
      as_light.hit.normal = pt.surface_normal;
      camera_densities[t - 2].rev = density(as_light, nullptr, *pt_minus, time);
    }
  }
  if (qs) {
    bdpt::Densities& qs_d = light_densities[s - 1];
    qs_d.rev = density(pt, pt_minus, *qs, time);
    qs_d.delta = false;
    if (qs_minus) light_densities[s - 2].rev = density(*qs, &pt, *qs_minus, time);
  }
  return bdpt::mis_weight(light_densities, camera_densities, delta_light);
}

void LightImage::add_now(const std::vector<bdpt::Splat>& splats) {
  const int window_width = window_.x1 - window_.x0;
  for (const bdpt::Splat& splat : splats) {
    const int x = static_cast<int>(splat.x), y = static_cast<int>(splat.y);
    if (x < window_.x0 || x >= window_.x1 || y < window_.y0 || y >= window_.y1) continue;
    const sg::vec3_rep L = sg::raw(splat.radiance);  // W/(m2 sr), as the film's other sums
    if (!std::isfinite(L.r) || !std::isfinite(L.g) || !std::isfinite(L.b)) continue;  // as the camera's invalid samples
    double* sum = &sums_[3 * (static_cast<size_t>(y - window_.y0) * window_width + (x - window_.x0))];
    sum[0] += L.r;
    sum[1] += L.g;
    sum[2] += L.b;
  }
}

}  // namespace safegi::render
