// The GPU path tracer's host: packs a scene, binds every array and constant
// by name through runtime_vk (checked against the shaders' symbol table),
// dispatches one sample of every pixel per pass, reads the film back.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::gpu {

struct GpuRenderOptions {
  int width = 0, height = 0;  // 0: the scene's
  int spp = 0;                // 0: the scene's
  std::uint32_t seed = 0;
  std::optional<std::string> device;  // runtime_vk's device choice (index or part of a name); unset: SAFEGI_VK_DEVICE
  std::string spirv_file, symbols_file;  // what safeglslc wrote for shaders/path_tracer.comp
  bool progress = false;
};

struct GpuRenderStats {
  int width = 0, height = 0, spp = 0;
  double seconds = 0;       // the dispatches and the read-back, not the scene's packing or the upload
  std::uint64_t rays = 0;   // extension and shadow rays the kernel counted
  std::string device;
  std::vector<std::string> unsupported;  // what the scene has that the GPU renderer leaves out
};

// The path-traced image (linear radiance, W·m⁻²·sr⁻¹ per channel).
render::Image render_on_gpu(const render::Scene& scene, const GpuRenderOptions& options, GpuRenderStats& stats);

// Where the build put the shaders (beside the program, else the build tree).
std::string default_spirv_file();
std::string default_symbols_file();

}  // namespace safegi::gpu
