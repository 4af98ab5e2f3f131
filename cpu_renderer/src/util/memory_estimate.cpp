#include "safegi/cpu_renderer/memory_estimate.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include <safegi/diagnostics/printable.hpp>

#include "integrators/bdpt.hpp"
#include "accel/bvh.hpp"
#include "accel/geometry.hpp"
#include "lights/light_choice.hpp"
#include "integrators/photon_map.hpp"
#include "integrators/sppm.hpp"
#include "film/pixel_filter.hpp"
#include "film/splat_film.hpp"

namespace safegi::render {

namespace {

// Per pixel of the window: render() holds three double sums and, as it makes
// the image from them, the three floats; afterwards (rank 0) the image, its
// 8-bit PNG copy and OpenImageIO's float copy for the EXR. The film needs the
// larger of the two.
constexpr uint64_t kFilmBytesPerPixel = std::max(3 * sizeof(double) + 3 * sizeof(float),
                                                 3 * sizeof(float) + 3 * sizeof(uint8_t) + 3 * sizeof(float));
// Per primitive: what the BVH's build holds (triangles eight-wide, spheres four).
constexpr uint64_t kTriangleBvhBytesPerPrimitive = kernel::Bvh8::kPeakBytesPerPrimitive;
constexpr uint64_t kSphereBvhBytesPerPrimitive = kernel::Bvh::kPeakBytesPerPrimitive;
// A triangle as added, and its lane of a leaf's block: a leaf starts at a block
// boundary, so a block may hold fewer than four. Counted at three a block: the
// SAH prices leaves by whole blocks, and meshes of 1e3 to 1e6 triangles (bench/scale,
// the pbrt-v3 test scenes) fill 3.8 to 4.
constexpr uint64_t kBlockBytesPerTriangle = sizeof(kernel::TriangleBlock) / 3;
constexpr uint64_t kTriangleBytes = sizeof(PrimitiveSet::Triangle) + kBlockBytesPerTriangle + kTriangleBvhBytesPerPrimitive;
constexpr uint64_t kSphereBytes = 2 * sizeof(PrimitiveSet::Sphere) + kSphereBvhBytesPerPrimitive;
// A worker's stack as far as a path of the deepest bounces touches it, and its counters.
constexpr uint64_t kBytesPerThread = 256 * 1024;
constexpr uint64_t kBytesPerTile = sizeof(PixelRect);
constexpr int kTileSide = 16;
// Per photon traced: the stored photon (at most one each), its grid bucket, its flag.
constexpr uint64_t kBytesPerPhoton = sizeof(Photon) + 2 * sizeof(uint32_t) + 1;

constexpr std::string_view kLimitVariable = "SAFEGI_RENDER_MEMORY_LIMIT";

std::optional<uint64_t> read_number(const std::string& path) {
  std::ifstream in(path);
  uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

// "MemAvailable:   8123456 kB" in /proc/meminfo.
std::optional<uint64_t> meminfo_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return std::nullopt;
}

// What the process's memory cgroup leaves: limit − usage; nullopt without a limit.
std::optional<uint64_t> cgroup_available() {
  std::ifstream self("/proc/self/cgroup");
  std::string line;
  while (std::getline(self, line)) {
    // v2: "0::/path"; v1: "N:memory:/path" (also "N:cpu,memory:/path").
    std::size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    std::string controllers = line.substr(first + 1, second - first - 1), path = line.substr(second + 1);
    std::optional<uint64_t> limit, usage;
    // Under a cgroup namespace (a container) the mount's root is the process's own cgroup.
    auto read_pair = [&](const std::string& mount, const char* limit_file, const char* usage_file) {
      for (const std::string& dir : {mount + path, mount}) {
        if ((limit = read_number(dir + limit_file))) {
          usage = read_number(dir + usage_file);
          return;
        }
      }
    };
    if (controllers.empty()) {
      read_pair("/sys/fs/cgroup", "/memory.max", "/memory.current");  // "max" (no limit) reads as no number
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      read_pair("/sys/fs/cgroup/memory", "/memory.limit_in_bytes", "/memory.usage_in_bytes");
      if (limit && *limit >= (uint64_t{1} << 60)) limit.reset();  // v1 says "no limit" with a huge number
    }
    if (limit) return *limit - std::min(*limit, usage.value_or(0));
  }
  return std::nullopt;
}

// "123", "64MiB", "1.5 GiB".
uint64_t parse_limit(const std::string& text) {
  static constexpr std::pair<std::string_view, double> kUnits[] = {
      {"", 1.0}, {"B", 1.0}, {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"TiB", 1099511627776.0}};
  std::istringstream in(text);
  double value = 0;
  std::string unit;
  if (in >> value) {
    in >> unit;
    std::string rest;
    for (const auto& [name, scale] : kUnits)
      if (unit == name && !(in >> rest) && value >= 0 && value * scale < 1.8e19)
        return static_cast<uint64_t>(value * scale);
  }
  throw std::runtime_error(std::string(kLimitVariable) + ": expected bytes, or a number with KiB, MiB, GiB or TiB, got '" +
                           text + "'");
}

}  // namespace

MemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options, int thread_count) {
  MemoryEstimate estimate;
  const RenderSettings& settings = options.settings;
  CropWindow window = options.crop.value_or(CropWindow{0, 0, settings.width, settings.height});
  estimate.width = std::max(0, window.width);
  estimate.height = std::max(0, window.height);
  const uint64_t pixels = static_cast<uint64_t>(estimate.width) * static_cast<uint64_t>(estimate.height);
  // A pixel filter: the sums of the samples' weights too.
  const uint64_t filter_bytes = PixelFilterSampler::is_plain_box(settings.filter) ? 0 : sizeof(double);
  estimate.film = pixels * (kFilmBytesPerPixel + filter_bytes);
  for (const Shape& shape : scene.shapes) {
    if (shape.type == Shape::Type::sphere) ++estimate.spheres;
    else estimate.triangles += shape.indices.size() / 3;
  }
  estimate.geometry = estimate.triangles * kTriangleBytes + estimate.spheres * kSphereBytes;
  const uint64_t tiles = static_cast<uint64_t>((estimate.width + kTileSide - 1) / kTileSide) *
                         static_cast<uint64_t>((estimate.height + kTileSide - 1) / kTileSide);
  estimate.thread_count = std::max(1, thread_count);
  estimate.threads = static_cast<uint64_t>(estimate.thread_count) * kBytesPerThread + tiles * kBytesPerTile;
  // Splatting: the tiles' buffers that wait to be added, and the one each thread fills.
  if (splats_samples(settings.filter))
    estimate.threads += static_cast<uint64_t>(estimate.thread_count) * (SplatFilm::kTilesAheadPerThread + 1) *
                        SplatFilm::tile_splats_bytes(settings.filter, kTileSide);
  // bdpt: light tracing's image, and the tiles' splats that wait to be added to it.
  if (settings.integrator == IntegratorType::bdpt) {
    estimate.film += pixels * 3 * sizeof(double);
    estimate.threads += LightImage::waiting_bytes(estimate.thread_count, settings.max_depth);
  }
  if (settings.integrator == IntegratorType::photon)
    estimate.photons = static_cast<uint64_t>(std::max(0, settings.photons)) * kBytesPerPhoton;
  if (settings.integrator == IntegratorType::sppm) estimate.film += sppm_bytes(settings, pixels);
  if (settings.light_strategy == LightStrategy::spatial) {
    uint64_t lights = scene.point_lights.size() + scene.spot_lights.size() + scene.distant_lights.size() +
                      (scene.environment ? 1 : 0);
    for (const Shape& shape : scene.shapes) lights += shape.emission ? 1 : 0;
    if (lights > 1) estimate.light_choice = SpatialLightChoice::most_bytes(lights);  // Lights makes none for one
  }
  return estimate;
}

uint64_t render_bytes_per_triangle() { return kTriangleBytes; }

std::optional<AvailableMemory> available_memory() {
  if (const char* forced = std::getenv(kLimitVariable.data()); forced && *forced)
    return AvailableMemory{parse_limit(forced), std::string(kLimitVariable)};
  std::optional<AvailableMemory> available;
  if (std::optional<uint64_t> bytes = meminfo_available()) available = AvailableMemory{*bytes, "MemAvailable in /proc/meminfo"};
  if (std::optional<uint64_t> bytes = cgroup_available(); bytes && (!available || *bytes < available->bytes))
    available = AvailableMemory{*bytes, "the limit of this process's cgroup, less its usage"};
  return available;
}

void check_render_memory(const Scene& scene, const RenderOptions& options, int thread_count, int processes) {
  std::optional<AvailableMemory> available = available_memory();
  if (!available) return;  // not Linux, or /proc unreadable: nothing to compare with
  const MemoryEstimate e = estimate_render_memory(scene, options, thread_count);
  const uint64_t needed = e.total() * static_cast<uint64_t>(std::max(1, processes));
  if (needed <= available->bytes / 100 * kUsableMemoryPercent) return;
  std::string message = "this render needs about " + format_bytes(needed) + " of memory";
  if (processes > 1) message += " (" + std::to_string(processes) + " ranks on this machine, " + format_bytes(e.total()) + " each)";
  message += ", more than " + std::to_string(kUsableMemoryPercent) + " % of the " + format_bytes(available->bytes) +
             " available (" + available->source + "): the " +
             std::to_string(e.width) + "x" + std::to_string(e.height) + " image " + format_bytes(e.film) +
             ", geometry and BVH " + format_bytes(e.geometry) + " (" + std::to_string(e.triangles) + " triangles, " +
             std::to_string(e.spheres) + " spheres), " + std::to_string(e.thread_count) +
             (e.thread_count == 1 ? " thread " : " threads ") + format_bytes(e.threads);
  if (e.photons > 0) message += ", photons " + format_bytes(e.photons);
  if (e.light_choice > 0) message += ", light choice " + format_bytes(e.light_choice);
  message += "; lower --resolution, render a --crop window";
  message += e.photons > 0 ? " or trace fewer --photons" : "";
  throw RenderMemoryError(message);
}

std::string out_of_memory_message(const std::string& doing) {
  std::string message = out_of_memory_text(doing);
  try {
    if (std::optional<AvailableMemory> available = available_memory())
      message += "; " + format_bytes(available->bytes) + " available (" + available->source + ")";
  } catch (const std::exception&) {  // a malformed SAFEGI_RENDER_MEMORY_LIMIT: said elsewhere
  }
  return message;
}

std::string format_bytes(uint64_t bytes) {
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + " B";
  double value = static_cast<double>(bytes) / 1024;
  std::size_t unit = 0;
  while (value >= 1024 && unit + 1 < std::size(kUnits)) value /= 1024, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
  return text;
}

}  // namespace safegi::render
