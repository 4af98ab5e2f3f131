// safegi-render-gpu: renders a scene file on a Vulkan device with the path
// tracer of shaders/ (annotated GLSL, checked by safeglslc), writing the
// same images as safegi-render. Same command line for the options that apply.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <safegi/diagnostics/command_line.hpp>

#include "gpu_render.hpp"
#include "safegi/cpu_renderer/image_io.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

int main(int argc, char** argv) {
  using namespace safegi::render;
  CLI::App app{"SafeGI GPU path tracer: renders a scene file (docs/scene-format.md) to EXR and PNG on a Vulkan "
               "device, with annotated GLSL compute shaders (docs/gpu-renderer.md)",
               std::filesystem::path(argv[0]).filename().string()};
  std::string scene_file, output = "render", resolution, device, length_unit;
  int spp = 0;
  std::uint32_t seed = 0;
  bool quiet = false, stats_json = false, pfm = false;
  safegi::gpu::GpuRenderOptions options;
  options.spirv_file = safegi::gpu::default_spirv_file();
  options.symbols_file = safegi::gpu::default_symbols_file();
  app.add_option("scene", scene_file, "scene file (.json, or a pbrt-v3 .pbrt)")->required();
  app.add_option("--length-unit", length_unit, "what one pbrt length unit is (m, cm, mm, in, ...; .pbrt scenes only)");
  app.add_option("-o,--output", output, "output name; writes NAME.exr (linear) and NAME.png (sRGB)");
  app.add_option("--spp", spp, "samples per pixel (default: the scene's)")->check(CLI::Range(1, 1 << 24));
  app.add_option("--seed", seed, "seed of the per-pixel sample sequences");
  app.add_option("--resolution", resolution, "image size WIDTHxHEIGHT (default: the scene's)");
  app.add_option("--device", device, "Vulkan device: its index or part of its name (default: SAFEGI_VK_DEVICE, else the first)");
  app.add_option("--spirv", options.spirv_file, "the path tracer's SPIR-V (default: the build's)");
  app.add_option("--symbols", options.symbols_file, "its symbol table (default: the build's)");
  app.add_flag("-q,--quiet", quiet, "no progress");
  app.add_flag("--pfm", pfm, "also write NAME.pfm (exact floats, e.g. for test references)");
  app.add_flag("--stats", stats_json, "print render statistics as one JSON line on stdout");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return safegi::exit_after_parse_error(app, error);
  }
  try {
    PbrtScene loaded = read_scene_file(scene_file, length_unit, read_image);  // as safegi-render reads it
    std::cerr << loaded.warnings;
    Scene scene = std::move(loaded.scene);
    if (!resolution.empty()) {
      ImageSize size = parse_resolution(resolution);
      options.width = size.width;
      options.height = size.height;
    }
    options.spp = spp;
    options.seed = seed;
    if (!device.empty()) options.device = device;
    options.progress = !quiet;
    safegi::gpu::GpuRenderStats stats;
    Image image = safegi::gpu::render_on_gpu(scene, options, stats);
    for (const std::string& line : stats.unsupported) std::fprintf(stderr, "warning: not on the GPU: %s\n", line.c_str());
    write_exr(with_image_extension(output, ".exr"), image);
    write_png(with_image_extension(output, ".png"), image);
    if (pfm) write_pfm(with_image_extension(output, ".pfm"), image);
    const double rays_per_second = stats.seconds > 0 ? static_cast<double>(stats.rays) / stats.seconds : 0.0;
    if (!quiet)
      std::fprintf(stderr, "%dx%d, %d spp in %.2f s on %s: %.2f M rays (%.2f M rays/s)\n", stats.width, stats.height,
                   stats.spp, stats.seconds, stats.device.c_str(), static_cast<double>(stats.rays) * 1e-6,
                   rays_per_second * 1e-6);
    if (stats_json)
      std::printf("{\"width\": %d, \"height\": %d, \"spp\": %d, \"seed\": %u, \"seconds\": %.4f, \"rays\": %llu, "
                  "\"rays_per_second\": %.0f, \"device\": \"%s\"}\n",
                  stats.width, stats.height, stats.spp, seed, stats.seconds, static_cast<unsigned long long>(stats.rays),
                  rays_per_second, stats.device.c_str());
  } catch (const CommandLineError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return safegi::kExitUsage;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
