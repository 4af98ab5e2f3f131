// The renderer's acceleration structure at scale, against Embree on the same
// rays (bench/scale/run.py drives it; never a test).
//
//   safegi-bench-scale --mesh heightfield|torus --triangles N [--resolution R] [--threads T] [--avx2 on|off]
//   safegi-bench-scale --mesh ... --triangles N --ply FILE   (writes the mesh, traces nothing)
//
// Generates the mesh (no files), builds our BVH (PrimitiveSet, as the renderer
// does) and, when built with Embree, an Embree scene over the same triangles,
// then traces three ray sets through both on one thread:
//   camera     one primary ray per pixel of a pinhole view of the whole mesh;
//   extension  from each camera hit, a cosine-distributed bounce;
//   shadow     from each camera hit to a point on a quad light above the mesh.
// Prints one JSON object: build seconds, bytes per triangle, rays per CPU-second
// per set, and how often the two structures disagree about a hit. `--avx2 off`
// traces through the SSE build of our traversal where the CPU has AVX2 (the
// one a CPU without it runs).
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "accel/geometry.hpp"

#ifdef SAFEGI_BENCH_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

using safegi::render::PrimitiveSet;
using safegi::render::kernel::Ray;
using safegi::render::kernel::Real3;
namespace kernel = safegi::render::kernel;

struct Mesh {
  std::vector<float> positions;  // x y z per vertex
  std::vector<uint32_t> indices;  // three per triangle
  Real3 vertex(uint32_t i) const { return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]}; }
  size_t triangle_count() const { return indices.size() / 3; }

  // Two triangles for each of `columns` × `rows` quads; `vertex(i, j)` names a quad's corner.
  template <class Vertex>
  void add_quads(size_t columns, size_t rows, Vertex&& vertex) {
    indices.reserve(indices.size() + 6 * columns * rows);
    for (size_t j = 0; j < rows; ++j)
      for (size_t i = 0; i < columns; ++i)
        indices.insert(indices.end(), {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j),
                                       vertex(i + 1, j + 1), vertex(i, j + 1)});
  }
};

// A grid of `cells`² quads over [-1, 1]², heights from a few sines: an open,
// gently rolling surface, every triangle visible from above.
Mesh height_field(size_t triangles) {
  size_t cells = std::max<size_t>(1, static_cast<size_t>(std::sqrt(triangles / 2.0)));
  Mesh mesh;
  mesh.positions.reserve(3 * (cells + 1) * (cells + 1));
  for (size_t j = 0; j <= cells; ++j)
    for (size_t i = 0; i <= cells; ++i) {
      float x = -1.0f + 2.0f * i / cells, y = -1.0f + 2.0f * j / cells;
      float z = 0.15f * std::sin(5 * x) * std::cos(4 * y) + 0.05f * std::sin(23 * x + 17 * y);
      mesh.positions.insert(mesh.positions.end(), {x, y, z});
    }
  mesh.add_quads(cells, cells, [&](size_t i, size_t j) { return static_cast<uint32_t>(j * (cells + 1) + i); });
  return mesh;
}

// A closed torus around z, its tube rippled: a dense mesh that occludes itself,
// so extension and shadow rays hit as often as they miss.
Mesh rippled_torus(size_t triangles) {
  size_t around = std::max<size_t>(3, static_cast<size_t>(std::sqrt(triangles / 2.0 * 3)));  // 3:1 aspect
  size_t tube = std::max<size_t>(3, triangles / 2 / around);
  Mesh mesh;
  mesh.positions.reserve(3 * around * tube);
  for (size_t j = 0; j < around; ++j)
    for (size_t i = 0; i < tube; ++i) {
      double u = 2 * M_PI * j / around, v = 2 * M_PI * i / tube;
      double r = 0.3 * (1 + 0.1 * std::sin(12 * u) * std::sin(7 * v));
      double ring = 0.7 + r * std::cos(v);
      mesh.positions.insert(mesh.positions.end(), {static_cast<float>(ring * std::cos(u)),
                                                   static_cast<float>(ring * std::sin(u)),
                                                   static_cast<float>(r * std::sin(v))});
    }
  mesh.add_quads(tube, around,
                 [&](size_t i, size_t j) { return static_cast<uint32_t>((j % around) * tube + (i % tube)); });
  return mesh;
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double thread_cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct RaySets {
  std::vector<Ray> camera, extension, shadow;
  std::vector<float> shadow_t_max;
};

Real3 orthogonal(Real3 n) {
  return std::fabs(n.x) > 0.5f ? kernel::normalize(kernel::cross(n, Real3{0, 1, 0}))
                               : kernel::normalize(kernel::cross(n, Real3{1, 0, 0}));
}

// Camera rays from above and to the side; bounces and shadow rays from their hits
// (found by our structure; both structures then trace the same rays).
RaySets make_rays(const PrimitiveSet& set, size_t resolution) {
  RaySets rays;
  const Real3 eye{2.2f, -2.6f, 2.4f}, target{0, 0, 0};
  Real3 forward = kernel::normalize(target - eye);
  Real3 right = kernel::normalize(kernel::cross(forward, Real3{0, 0, 1}));
  Real3 up = kernel::cross(right, forward);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (size_t y = 0; y < resolution; ++y)
    for (size_t x = 0; x < resolution; ++x) {
      float sx = (2.0f * (x + 0.5f) / resolution - 1) * 0.3f, sy = (2.0f * (y + 0.5f) / resolution - 1) * 0.3f;
      rays.camera.push_back({eye, kernel::normalize(forward + right * sx + up * sy), 0.0f});
    }
  for (const Ray& camera : rays.camera) {
    std::optional<kernel::Hit> hit = set.intersect(camera, kernel::kInfinity);
    if (!hit) continue;
    Real3 n = kernel::dot(hit->normal, camera.direction) < 0 ? hit->normal : hit->normal * -1.0f;
    Real3 origin = kernel::offset_ray_origin(hit->position, hit->position_error, n, n);
    float r = std::sqrt(unit(rng)), phi = 2 * float(M_PI) * unit(rng);
    Real3 t = orthogonal(n), b = kernel::cross(n, t);
    Real3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0f, 1 - r * r));
    rays.extension.push_back({origin, kernel::normalize(d), 0.0f});
    Real3 light{-0.5f + unit(rng), -0.5f + unit(rng), 1.5f};
    Real3 to_light = light - origin;
    float distance = kernel::length(to_light);
    rays.shadow.push_back({origin, to_light * (1.0f / distance), 0.0f});
    rays.shadow_t_max.push_back(distance * (1 - 1e-4f));
  }
  return rays;
}

struct Answers {
  std::vector<float> distance;  // infinity for a miss
  double cpu_seconds = 0;
};

// Enough repeats that each set is traced for about a CPU-second.
int repeats_for(size_t rays) { return static_cast<int>(std::clamp<size_t>(2000000 / std::max<size_t>(rays, 1), 1, 20)); }

template <class Trace>
Answers trace_all(const std::vector<Ray>& rays, Trace&& trace) {
  const int repeats = repeats_for(rays.size());
  Answers answers;
  answers.distance.resize(rays.size());
  double start = thread_cpu_seconds();
  for (int r = 0; r < repeats; ++r)
    for (size_t i = 0; i < rays.size(); ++i) answers.distance[i] = trace(i);
  answers.cpu_seconds = (thread_cpu_seconds() - start) / repeats;
  return answers;
}

// Rays on which two answers differ: a hit against a miss, or distances apart by
// more than a relative 1e-4 (grazing hits on a shared edge may go either way).
size_t disagreements(const Answers& a, const Answers& b) {
  size_t count = 0;
  for (size_t i = 0; i < a.distance.size(); ++i) {
    float x = a.distance[i], y = b.distance[i];
    if (std::isinf(x) != std::isinf(y) || (!std::isinf(x) && std::fabs(x - y) > 1e-4f * std::max(x, y))) ++count;
  }
  return count;
}

struct Options {
  std::string mesh = "heightfield";
  size_t triangles = 100000;
  size_t resolution = 512;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string ply;  // write the mesh here and stop
  bool avx2 = kernel::cpu_has_avx2();
};

// Binary little-endian PLY, as pbrt-v3 and safegi-render read it.
void write_ply(const Mesh& mesh, const std::string& path) {
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (!out) {
    std::fprintf(stderr, "safegi-bench-scale: cannot write '%s'\n", path.c_str());
    std::exit(1);
  }
  std::fprintf(out,
               "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
               "property float z\nelement face %zu\nproperty list uchar int vertex_indices\nend_header\n",
               mesh.positions.size() / 3, mesh.triangle_count());
  std::fwrite(mesh.positions.data(), sizeof(float), mesh.positions.size(), out);
  for (size_t i = 0; i < mesh.triangle_count(); ++i) {
    const unsigned char three = 3;
    std::fwrite(&three, 1, 1, out);
    std::fwrite(&mesh.indices[3 * i], sizeof(uint32_t), 3, out);
  }
  std::fclose(out);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--mesh") options.mesh = value;
    else if (flag == "--triangles") options.triangles = std::stoull(value);
    else if (flag == "--resolution") options.resolution = std::stoull(value);
    else if (flag == "--threads") options.threads = std::stoi(value);
    else if (flag == "--ply") options.ply = value;
    else if (flag == "--avx2") options.avx2 = value == "on" && kernel::cpu_has_avx2();
    else {
      std::fprintf(stderr, "safegi-bench-scale: unknown option '%s'\n", flag.c_str());
      std::exit(2);
    }
  }
  if (options.mesh != "heightfield" && options.mesh != "torus") {
    std::fprintf(stderr, "safegi-bench-scale: --mesh is heightfield or torus, not '%s'\n", options.mesh.c_str());
    std::exit(2);
  }
  return options;
}

struct SetAnswers {
  Answers camera, extension, shadow;
};

// The three sets through one structure: `scene.intersect(ray)` gives the
// nearest hit's distance, `scene.occluded(ray, t_max)` 0 for a hit; both
// infinity for a miss.
template <class Scene>
SetAnswers trace_sets(const RaySets& rays, const Scene& scene) {
  return {trace_all(rays.camera, [&](size_t i) { return scene.intersect(rays.camera[i]); }),
          trace_all(rays.extension, [&](size_t i) { return scene.intersect(rays.extension[i]); }),
          trace_all(rays.shadow, [&](size_t i) { return scene.occluded(rays.shadow[i], rays.shadow_t_max[i]); })};
}

// Our structure behind the interface trace_sets reads.
struct OurScene {
  const PrimitiveSet& set;
  float intersect(const Ray& ray) const {
    std::optional<kernel::Hit> hit = set.intersect(ray, kernel::kInfinity);
    return hit ? hit->distance : kernel::kInfinity;
  }
  float occluded(const Ray& ray, float t_max) const { return set.occluded(ray, t_max) ? 0.0f : kernel::kInfinity; }
};

void print_set(const char* name, size_t rays, const Answers& ours, const Answers* embree, bool last) {
  std::printf("  \"%s\": {\"rays\": %zu, \"ours_rays_per_cpu_second\": %.6g", name, rays, rays / ours.cpu_seconds);
  if (embree)
    std::printf(", \"embree_rays_per_cpu_second\": %.6g, \"disagreements\": %zu", rays / embree->cpu_seconds,
                disagreements(ours, *embree));
  std::printf("}%s\n", last ? "" : ",");
}

#ifdef SAFEGI_BENCH_EMBREE
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  double build_seconds = 0;
  static inline std::atomic<ssize_t> bytes{0}, peak_bytes{0};

  EmbreeScene(const Mesh& mesh, int threads) {
    std::string config = "threads=" + std::to_string(threads);
    device = rtcNewDevice(config.c_str());
    rtcSetDeviceMemoryMonitorFunction(device, [](void*, ssize_t change, bool) {
      ssize_t now = bytes += change;
      ssize_t peak = peak_bytes.load();
      while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {}
      return true;
    }, nullptr);
    double start = wall_seconds();
    scene = rtcNewScene(device);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Shared buffers: Embree reads the mesh in place, as our build reads the scene's.
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                               3 * sizeof(float), mesh.positions.size() / 3);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                               3 * sizeof(uint32_t), mesh.triangle_count());
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    build_seconds = wall_seconds() - start;
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }

  float intersect(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = {ray.origin.x, ray.origin.y, ray.origin.z, 0.0f, ray.direction.x, ray.direction.y, ray.direction.z,
                 0.0f, kernel::kInfinity, 0xFFFFFFFFu, 0, 0};
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &query);
    return query.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kernel::kInfinity : query.ray.tfar;
  }
  float occluded(const Ray& ray, float t_max) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay query{ray.origin.x, ray.origin.y, ray.origin.z, 0.0f, ray.direction.x, ray.direction.y, ray.direction.z,
                 0.0f, t_max, 0xFFFFFFFFu, 0, 0};
    rtcOccluded1(scene, &context, &query);
    return query.tfar < 0 ? 0.0f : kernel::kInfinity;  // Embree sets tfar to -inf on a hit
  }
};
#endif

}  // namespace

int main(int argc, char** argv) {
  Options options = parse(argc, argv);
  Mesh mesh = options.mesh == "torus" ? rippled_torus(options.triangles) : height_field(options.triangles);
  const size_t triangles = mesh.triangle_count();
  if (!options.ply.empty()) {
    write_ply(mesh, options.ply);
    return 0;
  }

  kernel::traversal_uses_avx2 = options.avx2;
  PrimitiveSet set;
  for (size_t i = 0; i < triangles; ++i)
    set.add_triangle(mesh.vertex(mesh.indices[3 * i]), mesh.vertex(mesh.indices[3 * i + 1]),
                     mesh.vertex(mesh.indices[3 * i + 2]), 0, static_cast<uint32_t>(i));
  double start = wall_seconds();
  set.build(options.threads);
  double build_seconds = wall_seconds() - start;

  RaySets rays = make_rays(set, options.resolution);
  const SetAnswers ours = trace_sets(rays, OurScene{set});

  std::printf("{\n  \"mesh\": \"%s\", \"triangles\": %zu, \"threads\": %d, \"avx2\": %s,\n", options.mesh.c_str(),
              triangles, options.threads, options.avx2 ? "true" : "false");
  std::printf("  \"ours_build_seconds\": %.6g, \"ours_bytes_per_triangle\": %.4g,\n", build_seconds,
              static_cast<double>(set.memory_bytes()) / triangles);
  const SetAnswers* embree_answers = nullptr;
#ifdef SAFEGI_BENCH_EMBREE
  EmbreeScene embree(mesh, options.threads);
  const SetAnswers embree_traced = trace_sets(rays, embree);
  embree_answers = &embree_traced;
  std::printf("  \"embree_build_seconds\": %.6g, \"embree_bytes_per_triangle\": %.4g,\n", embree.build_seconds,
              static_cast<double>(EmbreeScene::peak_bytes.load()) / triangles);
#endif
  print_set("camera", rays.camera.size(), ours.camera, embree_answers ? &embree_answers->camera : nullptr, false);
  print_set("extension", rays.extension.size(), ours.extension, embree_answers ? &embree_answers->extension : nullptr,
            false);
  print_set("shadow", rays.shadow.size(), ours.shadow, embree_answers ? &embree_answers->shadow : nullptr, true);
  std::printf("}\n");
}
