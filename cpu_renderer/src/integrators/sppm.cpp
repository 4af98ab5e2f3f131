#include "integrators/sppm.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include "materials/bsdf.hpp"
#include "scene/camera.hpp"
#include "accel/geometry.hpp"
#include "integrators/integrator.hpp"
#include "lights/lights.hpp"
#include "materials/material_mix.hpp"
#include "integrators/sampler.hpp"
#include "textures/surface_texture.hpp"

namespace safegi::render {

namespace {

// The photons' sample streams: "pixel" (photon index, kPhotonRow) of the
// sampler, sample index the iteration, apart from every camera pixel.
constexpr uint32_t kPhotonRow = 0x7370706du;  // "sppm"

// A surface point as the camera and photon passes see it: the chosen
// material, its BSDF's inputs, the shading frame and the outgoing direction.
struct Shaded {
  const Material* material = nullptr;
  Reflectance diffuse;
  Reflectance mix_weight{1.0f};
  bool from_inside = false;
  bool perturbed = false;
  NormalWorld facing;  // the geometric normal on the incoming ray's side
  ShadingFrame frame;
  DirectionShading wo;
};

// As Bdpt::shade: false where the surface does not scatter.
bool shade(const Scene& scene, const SurfaceTextures& textures, const SurfaceHit& hit, const TimedRay& ray,
           Shaded& out) {
  const Shape& shape = scene.shapes[hit.shape];
  out.from_inside = sg::dot(hit.normal, ray.d) > sg::zero;
  out.facing = out.from_inside ? -hit.normal : hit.normal;
  if (shape.material < 0) return false;
  const ConeFootprint footprint{.direction = ray.d};  // unfiltered textures
  const Material* chosen = &scene.materials[shape.material];
  out.mix_weight = Reflectance{1.0f};
  if (chosen->mix) {
    const MaterialChoice choice = choose_material(scene, textures, shape.material, hit, footprint, ray.time);
    if (!choice.material) return false;
    chosen = choice.material;
    if (choice.weighted) out.mix_weight = choice.weight;
  }
  out.diffuse = Reflectance{};
  if (const TexturedReflectance* diffuse = diffuse_of(*chosen))
    out.diffuse = diffuse->textured() ? textures.diffuse(*chosen, hit, footprint, ray.time) : diffuse->value;
  NormalWorld shading = hit.normal;
  out.perturbed = false;
  if (chosen->bump) {
    shading = textures.bumped_normal(*chosen->bump, hit, ray.time);
    out.perturbed = true;
  } else if (!shape.normals.empty()) {
    shading = textures.interpolated_normal(hit, ray.time);
    out.perturbed = true;
  }
  out.frame = ShadingFrame::from_normal(out.from_inside ? -shading : shading);
  out.wo = out.frame.to_local(-ray.d);
  out.material = chosen;
  return true;
}

// A pixel's visible point in the current iteration.
struct VisiblePoint {
  bool valid = false;
  PointWorld position;
  NormalWorld normal;  // the shading normal, on the camera's side
  ShadingFrame frame;
  DirectionShading wo;
  const Material* material = nullptr;
  Reflectance diffuse;
  bool from_inside = false;
  Reflectance beta;  // the camera path's throughput to it
};

// A photon's deposit: where it landed and what it carries.
struct Deposit {
  PointWorld position;
  DirectionWorld towards_light;
  NormalWorld normal;  // of the surface it landed on, on its side
  spectrum<dim::power> flux;
};

// Runs body(i) for i in [0, count) over `threads` threads.
template <class Body>
void parallel_for(size_t count, int threads, const Body& body) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < count; i = next++) body(i);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(worker);
  worker();
  for (std::thread& w : workers) w.join();
}

// A hashed uniform grid over the deposits, cells one search radius wide.
class DepositGrid {
 public:
  DepositGrid(std::vector<Deposit>&& deposits, Length cell) : deposits_(std::move(deposits)) {
    kernel::Bounds3 bounds;
    for (const Deposit& d : deposits_) bounds.extend(to_kernel(d.position));
    origin_ = bounds.empty() ? Real3{} : bounds.lower;
    cell_ = std::max(sg::raw(cell), std::numeric_limits<Real>::min());
    start_.assign(2 * deposits_.size() + 2, 0);
    std::vector<int64_t> buckets(deposits_.size());
    for (size_t i = 0; i < deposits_.size(); ++i) ++start_[(buckets[i] = bucket(cell_of(deposits_[i].position))) + 1];
    for (size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    std::vector<uint32_t> next(start_.begin(), start_.end() - 1);
    std::vector<Deposit> sorted(deposits_.size());
    for (size_t i = 0; i < deposits_.size(); ++i) sorted[next[buckets[i]]++] = deposits_[i];
    deposits_ = std::move(sorted);
  }

  // Calls visit(deposit) for each deposit in the 27 cells around `p` (every one within a cell's width).
  template <class Visit>
  void around(const PointWorld& p, const Visit& visit) const {
    if (deposits_.empty()) return;
    const std::array<int64_t, 3> c = cell_of(p);
    int64_t visited[27];
    int visited_count = 0;
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const int64_t b = bucket({c[0] + dx, c[1] + dy, c[2] + dz});
          if (std::find(visited, visited + visited_count, b) != visited + visited_count) continue;
          visited[visited_count++] = b;
          for (uint32_t i = start_[b]; i < start_[b + 1]; ++i) visit(deposits_[i]);
        }
  }

 private:
  std::array<int64_t, 3> cell_of(const PointWorld& p) const {
    const Real3 q = (to_kernel(p) - origin_) * (1 / cell_);
    // Clamped: a deposit far from the rest (or a tiny cell) must not overflow the cast.
    auto index = [](Real v) { return static_cast<int64_t>(std::floor(std::clamp(v, Real(-1e9), Real(1e9)))); };
    return {index(q.x), index(q.y), index(q.z)};
  }
  int64_t bucket(const std::array<int64_t, 3>& c) const {
    const uint64_t h = (static_cast<uint64_t>(c[0]) * 73856093u) ^ (static_cast<uint64_t>(c[1]) * 19349663u) ^
                       (static_cast<uint64_t>(c[2]) * 83492791u);
    return static_cast<int64_t>(h % (start_.size() - 1));
  }

  std::vector<Deposit> deposits_;
  Real3 origin_;
  Real cell_ = 1;
  std::vector<uint32_t> start_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

uint64_t sppm_bytes(const RenderSettings& settings, uint64_t pixels) {
  const uint64_t photons = settings.sppm_photons_per_iteration > 0
                               ? static_cast<uint64_t>(settings.sppm_photons_per_iteration)
                               : pixels;
  const uint64_t deposits = photons * static_cast<uint64_t>(std::clamp(settings.max_depth, 1, 5));
  return pixels * (sizeof(VisiblePoint) + sizeof(sppm::PixelStatistics) + 3 * sizeof(double)) +
         deposits * (3 * sizeof(Deposit) + 3 * sizeof(uint32_t) + sizeof(int64_t));
}

std::optional<std::string> sppm_refusal(const Scene& scene) {
  if (scene.has_media())
    return "the sppm integrator does not trace participating media or invisible surfaces: render with \"path\"";
  return std::nullopt;
}

Image render_sppm(const Scene& scene, const RenderOptions& options, RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (std::optional<std::string> refusal = sppm_refusal(scene)) throw std::invalid_argument(*refusal);
  if (options.partition && options.partition->parts() > 1)
    throw std::invalid_argument("the sppm integrator does not render over several processes");
  const RenderSettings& settings = options.settings;
  CropWindow window = options.crop.value_or(CropWindow{0, 0, settings.width, settings.height});
  window.x = std::clamp(window.x, 0, settings.width);
  window.y = std::clamp(window.y, 0, settings.height);
  window.width = std::clamp(window.width, 0, settings.width - window.x);
  window.height = std::clamp(window.height, 0, settings.height - window.y);
  const size_t pixels = static_cast<size_t>(window.width) * window.height;

  const int hardware_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = options.threads > 0 ? options.threads : hardware_threads;
  Geometry geometry(scene, threads);
  // Photons leave lights chosen by power, as pbrt-v3's SPPM; Ld samples them by the scene's strategy.
  Lights photon_lights(scene, LightStrategy::power);
  Lights lights(scene, settings.light_strategy);
  RenderSettings direct_settings = settings;
  direct_settings.integrator = IntegratorType::direct;
  const Integrator direct(scene, geometry, lights, direct_settings);
  const CameraRays camera(scene.camera, settings.width, settings.height);
  const SurfaceTextures textures(scene);

  const int iterations = std::max(1, settings.sppm_iterations);
  const uint64_t photons_per_iteration = settings.sppm_photons_per_iteration > 0
                                             ? static_cast<uint64_t>(settings.sppm_photons_per_iteration)
                                             : std::max<uint64_t>(pixels, 1);  // pbrt-v3: the cropped film's
  const Length initial_radius = settings.sppm_radius > sg::zero ? settings.sppm_radius : sg::from_raw<Length>(Real(1));
  const int max_depth = settings.max_depth;

  std::vector<sppm::PixelStatistics> statistics(pixels);
  for (sppm::PixelStatistics& p : statistics) p.radius2 = initial_radius * initial_radius;
  std::vector<double> direct_sums(3 * pixels, 0.0);
  std::vector<VisiblePoint> visible(pixels);
  std::vector<RayCounters> counters(static_cast<size_t>(threads));
  std::atomic<uint64_t> invalid{0};
  const Time open = scene.camera.shutter_open, span = scene.camera.shutter_close - scene.camera.shutter_open;
  constexpr uint64_t kPhotonChunk = 4096;
  const size_t chunks = static_cast<size_t>((photons_per_iteration + kPhotonChunk - 1) / kPhotonChunk);
  std::vector<std::vector<Deposit>> chunk_deposits(chunks);
  std::vector<RayCounters> chunk_counters(chunks);

  for (int iteration = 0; iteration < iterations; ++iteration) {
    const uint32_t sample_index = static_cast<uint32_t>(iteration);
    // Camera pass: one sample per pixel, row by row.
    std::vector<RayCounters> row_counters(static_cast<size_t>(window.height));
    parallel_for(static_cast<size_t>(window.height), threads, [&](size_t row) {
      RayCounters& counter = row_counters[row];
      const int y = window.y + static_cast<int>(row);
      for (int x = window.x; x < window.x + window.width; ++x) {
        const size_t pixel = row * static_cast<size_t>(window.width) + static_cast<size_t>(x - window.x);
        VisiblePoint& vp = visible[pixel];
        vp.valid = false;
        Sampler sampler(options.seed, static_cast<uint32_t>(x), static_cast<uint32_t>(y), sample_index);
        const Sample2 film = sampler.next_2d();
        const TimedRay camera_ray =
            camera.generate_at(static_cast<Real>(x) + film.u, static_cast<Real>(y) + film.v, sampler);
        ++counter.camera;
        // Ld: emission and direct light at the end of the specular chains (direct lighting's estimate).
        const sg::vec3_rep L = sg::raw(direct.radiance(camera_ray, sampler, counter));
        if (std::isfinite(L.r) && std::isfinite(L.g) && std::isfinite(L.b)) {
          direct_sums[3 * pixel] += L.r;
          direct_sums[3 * pixel + 1] += L.g;
          direct_sums[3 * pixel + 2] += L.b;
        } else {
          ++invalid;
        }
        // The visible point: through specular bounces (one lobe sampled) to the first other surface.
        TimedRay ray = camera_ray;
        Reflectance beta{1.0f};
        for (int depth = 0; depth < max_depth; ++depth) {
          std::optional<SurfaceHit> hit = geometry.intersect(ray);
          ++counter.extension;
          if (!hit) break;
          Shaded s;
          if (!shade(scene, textures, *hit, ray, s)) break;
          const Bsdf bsdf(*s.material, s.diffuse, s.from_inside);
          beta = beta * s.mix_weight;
          if (!bsdf.is_specular()) {
            vp = {.valid = true, .position = hit->position, .normal = s.frame.normal(), .frame = s.frame, .wo = s.wo,
                  .material = s.material, .diffuse = s.diffuse, .from_inside = s.from_inside, .beta = beta};
            break;
          }
          const Real u_lobe = sampler.next_1d();
          const Sample2 u = sampler.next_2d();
          std::optional<BsdfSample> sample = bsdf.sample(s.wo, u_lobe, u.u, u.v, Transport::radiance);
          if (!sample) break;
          beta = beta * sample->weight;
          if (sg::is_black(beta)) break;
          ray = spawn_ray(*hit, s.frame.from_local(sample->wi), ray.time);
        }
      }
    });
    for (size_t row = 0; row < row_counters.size(); ++row) {
      counters[0].camera += row_counters[row].camera;
      counters[0].extension += row_counters[row].extension;
      counters[0].shadow += row_counters[row].shadow;
    }

    // Photon pass: chunks of photons, their deposits concatenated in photon order.
    Length largest = sg::zero;
    for (size_t pixel = 0; pixel < pixels; ++pixel)
      if (visible[pixel].valid) largest = std::max(largest, sg::sqrt(statistics[pixel].radius2));
    if (!photon_lights.empty() && largest > sg::zero) {
      parallel_for(chunks, threads, [&](size_t chunk) {
        std::vector<Deposit>& deposits = chunk_deposits[chunk];
        deposits.clear();
        RayCounters& counter = chunk_counters[chunk];
        const uint64_t begin = chunk * kPhotonChunk, end = std::min(photons_per_iteration, begin + kPhotonChunk);
        for (uint64_t i = begin; i < end; ++i) {
          Sampler sampler(options.seed, static_cast<uint32_t>(i), kPhotonRow, sample_index);
          const Time time = open + sampler.next_1d() * span;
          const Real u_light = sampler.next_1d();
          const Sample2 position = sampler.next_2d(), direction = sampler.next_2d();
          std::optional<PhotonEmission> emitted =
              photon_lights.sample_emission(time, u_light, position.u, position.v, direction.u, direction.v);
          if (!emitted) continue;
          spectrum<dim::power> flux = emitted->flux;
          const Real3 origin = kernel::offset_ray_origin(to_kernel(emitted->origin), emitted->origin_error,
                                                         emitted->surface_normal, to_kernel(emitted->direction));
          TimedRay ray{sg::ray<World>{from_kernel<PointWorld>(origin), emitted->direction}, time};
          for (int depth = 0; depth < max_depth; ++depth) {
            std::optional<SurfaceHit> hit = geometry.intersect(ray);
            ++counter.extension;
            if (!hit) break;
            Shaded s;
            if (!shade(scene, textures, *hit, ray, s)) break;
            const Bsdf bsdf(*s.material, s.diffuse, s.from_inside);
            // The first hit's light is Ld's (direct lighting): deposits from the second on.
            if (depth > 0 && !bsdf.is_specular()) deposits.push_back({hit->position, -ray.d, s.facing, flux});
            const Real u_lobe = sampler.next_1d();
            const Sample2 u = sampler.next_2d();
            std::optional<BsdfSample> sample = bsdf.sample(s.wo, u_lobe, u.u, u.v, Transport::importance);
            if (!sample) break;
            const DirectionWorld wi = s.frame.from_local(sample->wi);
            if (s.perturbed && (sg::dot(s.facing, wi) > sg::zero) != (sample->wi.z() > 0)) break;
            const spectrum<dim::power> next = flux * (sample->weight * s.mix_weight);
            if (sg::is_black(next)) break;
            // Russian roulette on the change of flux (pbrt-v3's SPPM).
            const Real survival = std::min(Real(1), sg::max_component(next) / sg::max_component(flux));
            if (survival < 1) {
              if (sampler.next_1d() >= survival) break;
              flux = next / survival;
            } else {
              flux = next;
            }
            ray = spawn_ray(*hit, wi, time);
          }
        }
      });
      size_t total = 0;
      for (const std::vector<Deposit>& d : chunk_deposits) total += d.size();
      std::vector<Deposit> all;
      all.reserve(total);
      for (const std::vector<Deposit>& d : chunk_deposits) all.insert(all.end(), d.begin(), d.end());
      for (const RayCounters& c : chunk_counters) counters[0].extension += c.extension;
      std::fill(chunk_counters.begin(), chunk_counters.end(), RayCounters{});
      const DepositGrid grid(std::move(all), largest);

      // Gather: each visible point the deposits within its radius, in the grid's order.
      parallel_for(static_cast<size_t>(window.height), threads, [&](size_t row) {
        for (size_t pixel = row * window.width; pixel < (row + 1) * window.width; ++pixel) {
          const VisiblePoint& vp = visible[pixel];
          if (!vp.valid) continue;
          sppm::PixelStatistics& p = statistics[pixel];
          const Bsdf bsdf(*vp.material, vp.diffuse, vp.from_inside);
          const bool transmits = bsdf.transmits();
          sppm::GatheredFlux phi;
          Real m = 0;
          grid.around(vp.position, [&](const Deposit& d) {
            if (!(sg::distance_squared(d.position, vp.position) < p.radius2)) return;
            // Deposits on a surface of another orientation (a corner) do not
            // count, nor those on the far side unless the surface transmits.
            const Real facing = sg::dot(d.normal, vp.normal);
            const bool near_side = facing >= Real(0.5);
            if (!near_side && !(transmits && facing <= Real(-0.5))) return;
            const DirectionShading wi = vp.frame.to_local(d.towards_light);
            phi += bsdf.eval(vp.wo, wi) * d.flux;
            m += 1;
          });
          sppm::update(p, m, vp.beta * phi);
        }
      });
    }
  }

  // L = Ld / iterations + τ / (N_e π r²).
  const double emitted = static_cast<double>(photons_per_iteration) * iterations;
  Image image;
  image.width = window.width;
  image.height = window.height;
  image.rgb.resize(3 * pixels);
  for (size_t pixel = 0; pixel < pixels; ++pixel) {
    const sg::vec3_rep indirect = sg::raw(sppm::indirect(statistics[pixel], emitted));
    const double rgb[3] = {indirect.r, indirect.g, indirect.b};
    for (int c = 0; c < 3; ++c)
      image.rgb[3 * pixel + c] =
          static_cast<float>((direct_sums[3 * pixel + c] / iterations + rgb[c]) * settings.film_scale);
  }
  if (stats) {
    *stats = RenderStats{};
    for (const RayCounters& c : counters) {
      stats->camera_rays += c.camera;
      stats->extension_rays += c.extension;
      stats->shadow_rays += c.shadow;
    }
    stats->invalid_samples = invalid;
    stats->samples_per_pixel = iterations;
    stats->threads = threads;
    stats->seconds = seconds_since(start);
  }
  return image;
}

}  // namespace safegi::render
