#include "integrators/photon_map.hpp"

#include <algorithm>
#include <cmath>

#include "materials/bsdf.hpp"
#include "materials/material_mix.hpp"
#include "integrators/sampler.hpp"

namespace safegi::render {

namespace {

// The photons' own sample streams: "pixel" (index, kPhotonRow) of the sampler,
// apart from every camera pixel.
constexpr uint32_t kPhotonRow = 0x70686f74u;

// The total area of the shapes marked in `which`.
quantity<dim::area> total_area(const Scene& scene, const std::vector<bool>& which) {
  quantity<dim::area> area = sg::zero;
  for (size_t s = 0; s < scene.shapes.size(); ++s) {
    if (!which[s]) continue;
    const Shape& shape = scene.shapes[s];
    const RenderFromObject& render_from_object = shape.render_from_object;
    if (shape.type == Shape::Type::sphere) {
      Length r = placed_radius(render_from_object, shape.radius);
      area += 4 * kPi * r * r;
      continue;
    }
    for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
      PointWorld a = render_from_object(shape.positions[shape.indices[i]]), b = render_from_object(shape.positions[shape.indices[i + 1]]),
                 c = render_from_object(shape.positions[shape.indices[i + 2]]);
      area += Real(0.5) * sg::length(sg::cross(b - a, c - a));
    }
  }
  return area;
}

}  // namespace

PhotonMap::PhotonMap(const Scene& scene, const Geometry& geometry, const Lights& lights, const SurfaceTextures& textures,
                     const RenderSettings& settings, uint32_t seed) {
  std::vector<bool> received(scene.shapes.size(), false);
  trace(scene, geometry, lights, textures, settings, seed, received);
  radius_ = settings.photon_radius;
  if (!(radius_ > sg::zero)) {
    // About 64 photons per disc if they covered the shapes they landed on evenly.
    const Real stored = static_cast<Real>(std::max<size_t>(photons_.size(), 1));
    radius_ = sg::sqrt(64 * total_area(scene, received) / (kPi * stored));
    if (!(radius_ > sg::zero)) radius_ = sg::from_raw<Length>(Real(1));
  }
  build_grid();
}

void PhotonMap::trace(const Scene& scene, const Geometry& geometry, const Lights& lights,
                      const SurfaceTextures& textures, const RenderSettings& settings, uint32_t seed,
                      std::vector<bool>& received) {
  if (lights.empty()) return;
  const int count = settings.photons;
  const Time open = scene.camera.shutter_open, span = scene.camera.shutter_close - scene.camera.shutter_open;
  for (int i = 0; i < count; ++i) {
    Sampler sampler(seed, static_cast<uint32_t>(i), kPhotonRow, 0);
    Time time = open + sampler.next_1d() * span;
    Real u_light = sampler.next_1d();
    Sample2 position = sampler.next_2d(), direction = sampler.next_2d();
    std::optional<PhotonEmission> emitted =
        lights.sample_emission(time, u_light, position.u, position.v, direction.u, direction.v);
    if (!emitted) continue;
    spectrum<dim::power> flux = emitted->flux / static_cast<Real>(count);
    Real3 origin = kernel::offset_ray_origin(to_kernel(emitted->origin), emitted->origin_error, emitted->surface_normal,
                                             to_kernel(emitted->direction));
    TimedRay segment{ray<World>{from_kernel<PointWorld>(origin), emitted->direction}, time};
    for (int depth = 0; depth < settings.max_depth; ++depth) {
      std::optional<SurfaceHit> hit = geometry.intersect(segment);
      ++traced_rays_;
      if (!hit) break;
      const Shape& shape = scene.shapes[hit->shape];
      if (shape.material < 0) break;
      const bool from_inside = sg::dot(hit->normal, segment.d) > sg::zero;
      NormalWorld facing = from_inside ? -hit->normal : hit->normal;
      // A caustic photon is one that reaches a non-specular surface through
      // specular bounces only; where it lands, its path ends (the path tracer
      // has the rest, direct light included). On a mix of a specular material
      // and another it lands whichever the hit picks (the gather weighs it by
      // the other's share) and goes on only through the specular one.
      if (depth > 0 && scatters_non_specularly(scene, shape.material)) {
        photons_.push_back({hit->position, -segment.d, facing, flux});
        received[hit->shape] = true;
      }
      const MaterialChoice choice = choose_material(scene, textures, shape.material, *hit, ConeFootprint{.direction = segment.d}, time);
      if (!choice.material || !is_specular(choice.material->model)) break;
      if (choice.weighted) flux = flux * choice.weight;
      const Material& material = *choice.material;
      const Reflectance no_diffuse{};  // specular materials have none
      Bsdf bsdf(material, no_diffuse, from_inside);
      ShadingFrame frame = ShadingFrame::from_normal(facing);
      DirectionShading wo = frame.to_local(-segment.d);
      Real u_lobe = sampler.next_1d();
      Sample2 u = sampler.next_2d();
      std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u.u, u.v, Transport::importance);
      if (!scattered) break;
      spectrum<dim::power> next = flux * scattered->weight;
      if (sg::is_black(next)) break;
      if (depth >= 3) {  // Russian roulette on the change of flux
        Real survival = std::min(Real(0.95), sg::max_component(next) / sg::max_component(flux));
        if (sampler.next_1d() >= survival) break;
        next = next / survival;
      }
      flux = next;
      segment = spawn_ray(*hit, frame.from_local(scattered->wi), time);
    }
  }
}

int64_t PhotonMap::cell_key(int64_t x, int64_t y, int64_t z) const {
  const uint64_t h = (static_cast<uint64_t>(x) * 73856093u) ^ (static_cast<uint64_t>(y) * 19349663u) ^
                     (static_cast<uint64_t>(z) * 83492791u);
  return static_cast<int64_t>(h % (bucket_start_.size() - 1));
}

void PhotonMap::build_grid() {
  kernel::Bounds3 bounds;
  for (const Photon& photon : photons_) bounds.extend(to_kernel(photon.position));
  grid_origin_ = bounds.empty() ? Real3{} : bounds.lower;
  cell_size_ = sg::raw(radius_);
  bucket_start_.assign(2 * photons_.size() + 2, 0);
  auto bucket_of = [&](const Photon& photon) {
    Real3 p = (to_kernel(photon.position) - grid_origin_) * (1 / cell_size_);
    return cell_key(static_cast<int64_t>(std::floor(p.x)), static_cast<int64_t>(std::floor(p.y)),
                    static_cast<int64_t>(std::floor(p.z)));
  };
  // Counting sort by bucket.
  std::vector<int64_t> buckets(photons_.size());
  for (size_t i = 0; i < photons_.size(); ++i) ++bucket_start_[(buckets[i] = bucket_of(photons_[i])) + 1];
  for (size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
  std::vector<uint32_t> next(bucket_start_.begin(), bucket_start_.end() - 1);
  std::vector<Photon> sorted(photons_.size());
  for (size_t i = 0; i < photons_.size(); ++i) sorted[next[buckets[i]]++] = photons_[i];
  photons_ = std::move(sorted);
}

Radiance PhotonMap::estimate(const SurfaceHit& hit, const ShadingFrame& frame, const Bsdf& bsdf,
                             DirectionShading wo) const {
  Radiance reflected;
  if (photons_.empty()) return reflected;
  const Real3 p = (to_kernel(hit.position) - grid_origin_) * (1 / cell_size_);
  const int64_t cx = static_cast<int64_t>(std::floor(p.x)), cy = static_cast<int64_t>(std::floor(p.y)),
                cz = static_cast<int64_t>(std::floor(p.z));
  const quantity<dim::area> radius2 = radius_ * radius_;
  const bool transmits = bsdf.transmits();
  int64_t visited[27];
  int visited_count = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int64_t bucket = cell_key(cx + dx, cy + dy, cz + dz);
        // Two cells can hash to one bucket: visit each bucket once.
        if (std::find(visited, visited + visited_count, bucket) != visited + visited_count) continue;
        visited[visited_count++] = bucket;
        for (uint32_t i = bucket_start_[bucket]; i < bucket_start_[bucket + 1]; ++i) {
          const Photon& photon = photons_[i];
          quantity<dim::area> d2 = sg::distance_squared(photon.position, hit.position);
          if (!(d2 < radius2)) continue;
          // Photons of another surface orientation (a corner) do not count,
          // nor those on the far side (of a thin wall) unless the surface lets
          // light through; a photon counts on the side it arrived from, which
          // a perturbed shading frame must agree with.
          const Real facing = sg::dot(photon.normal, frame.normal());
          const bool near_side = facing >= Real(0.5);
          if (!near_side && !(transmits && facing <= Real(-0.5))) continue;
          const DirectionShading wi = frame.to_local(photon.towards_light);
          if ((wi.z() > 0) != near_side) continue;
          Brdf f = bsdf.eval(wo, wi);
          reflected += f * photon.flux * cone_kernel(sg::sqrt(d2), radius_);
        }
      }
  return reflected;
}

}  // namespace safegi::render
