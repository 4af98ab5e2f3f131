// What a render will allocate, estimated before it allocates anything, and
// what the machine has: a render that cannot fit is refused with both figures
// instead of swapping the machine to a halt or ending in std::bad_alloc
// (docs/cpu-renderer.md, "Memory").
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// Bytes, by what needs them; the scene itself is loaded already and not counted.
struct MemoryEstimate {
  int width = 0, height = 0;  // the rendered window
  uint64_t film = 0;          // per-pixel double sums and the float image, or the image and its encoded copies
  uint64_t geometry = 0;      // world-space triangles and spheres, their BVH and its build
  uint64_t threads = 0;       // per worker thread: its stack and counters; the tile list
  uint64_t photons = 0;       // the photon integrator's photons and their grid
  uint64_t light_choice = 0;  // the spatial light choice's voxel tables, at most
  uint64_t triangles = 0, spheres = 0;
  int thread_count = 0;
  uint64_t total() const { return film + geometry + threads + photons + light_choice; }
};

MemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options, int thread_count);

struct AvailableMemory {
  uint64_t bytes = 0;
  std::string source;  // where the figure comes from, for the message
};

// The least of: MemAvailable in /proc/meminfo, and what the process's cgroup
// (v2 memory.max, v1 memory.limit_in_bytes) leaves of its limit. The
// environment variable SAFEGI_RENDER_MEMORY_LIMIT (bytes, or a number with
// KiB, MiB, GiB or TiB) replaces both, for tests. nullopt: nothing could be read.
std::optional<AvailableMemory> available_memory();

// A render that does not fit; what() names the estimate, its parts and the available memory.
class RenderMemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A render may take this share of the available memory: the estimate leaves
// out the libraries' and the allocator's own use, and other processes go on
// allocating while it runs.
inline constexpr uint64_t kUsableMemoryPercent = 80;

// What a render holds per triangle of its scene (its world-space record, and
// the BVH while built): what an importer that makes triangles weighs them by.
uint64_t render_bytes_per_triangle();

// Throws RenderMemoryError when the estimate times `processes` (the ranks
// sharing this machine) exceeds kUsableMemoryPercent of the available memory.
void check_render_memory(const Scene& scene, const RenderOptions& options, int thread_count, int processes = 1);

// What main() says when an allocation failed anyway: what was being done and
// how much memory was available.
std::string out_of_memory_message(const std::string& doing);

// "512 B", "3.5 KiB", "9.5 GiB".
std::string format_bytes(uint64_t bytes);

}  // namespace safegi::render
