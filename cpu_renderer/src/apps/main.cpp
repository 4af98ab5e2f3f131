// safegi-render / safegi-render-unchecked: renders a scene file to EXR + PNG.
// The same source builds both programs; only the typed library's mode differs.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sys/resource.h>
#include <unistd.h>

#include <safegi/diagnostics/command_line.hpp>

#include "distributed/distributed.hpp"
#include "safegi/cpu_renderer/memory_estimate.hpp"
#include "safegi/cpu_renderer/image_io.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"
#include "safegi/cpu_renderer/precision.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace {

double cpu_seconds(const rusage& usage) {
  return usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec + usage.ru_stime.tv_usec * 1e-6;
}

rusage resource_usage() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace safegi::render;
  // Under mpirun, one rank of a distributed render (docs/cpu-renderer.md); else a single process.
  DistributedSession session(argc, argv);
  CLI::App app{"SafeGI CPU path tracer: renders a scene file (docs/scene-format.md) to EXR and PNG",
               std::filesystem::path(argv[0]).filename().string()};
  std::string scene_file, output = "render", resolution, crop, integrator, mis, russian_roulette, length_unit,
      light_strategy;
  int spp = 0, threads = 0, max_depth = 0, light_samples = 0, roulette_depth = -1;
  uint32_t seed = 0;
  double time_budget = 0;
  bool quiet = false, stats_json = false, pfm = false;
  app.add_option("scene", scene_file, "scene file (.json, or a pbrt-v3 .pbrt)")->required();
  app.add_option("--length-unit", length_unit, "what one pbrt length unit is (m, cm, mm, in, ...; .pbrt scenes only)");
  app.add_option("-o,--output", output, "output name; writes NAME.exr (linear) and NAME.png (sRGB)");
  app.add_option("--spp", spp, "samples per pixel (with --time-budget: the most to take)")->check(CLI::Range(1, 1 << 24));
  app.add_option("--threads", threads, "worker threads (per rank under mpirun; default: all cores)")->check(CLI::Range(1, 1024));
  app.add_option("--seed", seed, "seed of the per-pixel sample sequences");
  app.add_option("--resolution", resolution, "image size WIDTHxHEIGHT (default: the scene's)");
  app.add_option("--crop", crop, "render only the window X,Y,WIDTH,HEIGHT (pixels)");
  app.add_option("--time-budget", time_budget, "render until this many seconds are spent")->check(CLI::PositiveNumber);
  app.add_option("--integrator", integrator, "direct, path, photon, bdpt or sppm (default: the scene's)")
      ->check(CLI::IsMember({"direct", "path", "photon", "bdpt", "sppm"}));
  int photons = 0;
  double photon_radius = 0;
  app.add_option("--photons", photons, "photons traced by the photon integrator (default: the scene's, 200000)")
      ->check(CLI::Range(1, 1 << 28));
  app.add_option("--photon-radius", photon_radius, "the photon density estimate's radius in metres (default: from the scene)")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-depth", max_depth, "longest path, in bounces (default: the scene's)")->check(CLI::Range(1, 1024));
  app.add_option("--mis", mis, "on: light and BSDF sampling combined by MIS; off: area lights by light sampling only")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--light-samples", light_samples, "shadow rays per shading point for direct lighting (default: 1)")
      ->check(CLI::Range(1, 1024));
  app.add_option("--light-strategy", light_strategy,
                 "which lights shadow rays go to: power, uniform, spatial (one light each) or all (default: the scene's)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kLightStrategyNames), std::end(kLightStrategyNames))));
  app.add_option("--rr", russian_roulette, "Russian roulette on or off (off: paths end at --max-depth)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--rr-depth", roulette_depth, "bounces before Russian roulette starts (default: 3)")
      ->check(CLI::Range(0, 1024));
  app.add_flag("-q,--quiet", quiet, "no progress bar");
  app.add_flag("--pfm", pfm, "also write NAME.pfm (exact floats, e.g. for test references)");
  app.add_flag("--stats", stats_json, "print render statistics as one JSON line on stdout");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // Every rank parses alike; one prints.
    if (session.is_root()) return safegi::exit_after_parse_error(app, error);
    return error.get_exit_code() == 0 ? safegi::kExitSuccess : safegi::kExitUsage;
  }

  // What the program is doing, for the message when memory runs out anyway.
  std::string doing = "loading the scene";
  try {
    std::optional<CropWindow> scene_crop;
    PbrtScene loaded = read_scene_file(scene_file, length_unit, read_image);
    if (session.is_root()) std::cerr << loaded.warnings;
    Scene scene = std::move(loaded.scene);
    scene_crop = loaded.crop;
    if (std::optional<PrecisionReport> unresolved = check_precision(scene); unresolved && session.is_root())
      std::cerr << describe(*unresolved, scene);
    RenderOptions options;
    options.settings = scene.settings;
    options.crop = scene_crop;
    if (spp > 0) options.settings.spp = spp;
    else if (time_budget > 0) options.settings.spp = 1 << 24;
    if (max_depth > 0) options.settings.max_depth = max_depth;
    if (!integrator.empty())
      options.settings.integrator = integrator == "direct"   ? IntegratorType::direct
                                    : integrator == "path"   ? IntegratorType::path
                                    : integrator == "photon" ? IntegratorType::photon
                                    : integrator == "sppm"   ? IntegratorType::sppm
                                                             : IntegratorType::bdpt;
    if (photons > 0) options.settings.photons = photons;
    if (photon_radius > 0) options.settings.photon_radius = static_cast<Real>(photon_radius) * units::metre;
    if (!mis.empty()) options.settings.mis = mis == "on";
    if (light_samples > 0) options.settings.light_samples = light_samples;
    if (!light_strategy.empty()) options.settings.light_strategy = *light_strategy_named(light_strategy);
    if (!russian_roulette.empty()) options.settings.russian_roulette = russian_roulette == "on";
    if (roulette_depth >= 0) options.settings.russian_roulette_depth = roulette_depth;
    if (!resolution.empty()) {
      ImageSize size = parse_resolution(resolution);
      options.settings.width = size.width;
      options.settings.height = size.height;
      options.crop.reset();  // a pbrt Film's crop window was in pixels of its own resolution
    }
    if (!crop.empty()) {
      std::smatch match;
      if (!std::regex_match(crop, match, std::regex(R"((\d{1,5}),(\d{1,5}),(\d{1,5}),(\d{1,5}))")))
        throw CommandLineError("--crop: expected X,Y,WIDTH,HEIGHT, got '" + safegi::escape_unprintable(crop) + "'");
      CropWindow window{std::stoi(match[1]), std::stoi(match[2]), std::stoi(match[3]), std::stoi(match[4])};
      if (window.width < 1 || window.height < 1 || window.x + window.width > options.settings.width ||
          window.y + window.height > options.settings.height)
        throw CommandLineError("--crop: the window must be non-empty and inside the image");
      options.crop = window;
    }
    options.threads = threads;
    options.seed = seed;
    options.time_budget_seconds = time_budget;
    options.progress = !quiet;

    // Refused before anything is allocated, on every rank alike (the setup's agreement).
    check_render_memory(scene, options, threads > 0 ? threads : session.default_threads(), session.ranks_on_this_node());

    RenderStats stats;
    doing = "rendering";
    rusage before_render = resource_usage();
    Image image = session.render(scene, options, &stats);
    double rank_render_cpu_seconds = cpu_seconds(resource_usage()) - cpu_seconds(before_render);
    double render_cpu_seconds = session.sum_over_ranks(rank_render_cpu_seconds);
    double busiest_rank_cpu_seconds = session.max_over_ranks(rank_render_cpu_seconds);
    // Rank 0 writes the image and reports for all; the others stop here.
    double other_ranks_cpu_seconds = session.sum_over_ranks(session.is_root() ? 0.0 : cpu_seconds(resource_usage()));
    if (!session.is_root()) return 0;
    doing = "writing the image";
    write_exr(with_image_extension(output, ".exr"), image);
    write_png(with_image_extension(output, ".png"), image);
    if (pfm) write_pfm(with_image_extension(output, ".pfm"), image);

    rusage usage = resource_usage();
    double rays_per_second = stats.seconds > 0 ? static_cast<double>(stats.total_rays()) / stats.seconds : 0.0;
    // CPU time: on a shared machine, rays per CPU-second of the render is the
    // per-core throughput even when wall-clock time is not.
    double process_cpu_seconds = cpu_seconds(usage) + other_ranks_cpu_seconds;
    if (!quiet)
      std::fprintf(stderr, "%dx%d, %d spp in %.2f s: %.2f M rays (%.2f M rays/s), peak memory %.1f MiB\n",
                   image.width, image.height, stats.samples_per_pixel, stats.seconds, stats.total_rays() * 1e-6,
                   rays_per_second * 1e-6, usage.ru_maxrss / 1024.0);
    if (stats.invalid_samples > 0)
      std::fprintf(stderr, "warning: %llu samples were NaN or infinite and were dropped\n",
                   static_cast<unsigned long long>(stats.invalid_samples));
    if (stats_json) {
      const RenderSettings& used = options.settings;
      std::printf(
          "{\"width\": %d, \"height\": %d, \"spp\": %d, \"samples\": %llu, \"ranks\": %d, \"threads\": %d, "
          "\"seed\": %u, "
          "\"integrator\": \"%s\", \"max_depth\": %d, \"mis\": %s, \"light_samples\": %d, \"light_strategy\": \"%s\", "
          "\"russian_roulette\": %s, \"russian_roulette_depth\": %d, "
          "\"seconds\": %.4f, \"render_cpu_seconds\": %.3f, \"busiest_rank_render_cpu_seconds\": %.3f, "
          "\"cpu_seconds\": %.3f, "
          "\"camera_rays\": %llu, \"extension_rays\": %llu, \"shadow_rays\": %llu, \"rays\": %llu, "
          "\"rays_per_second\": %.0f, \"samples_per_second\": %.0f, \"rays_per_cpu_second\": %.0f, "
          "\"peak_memory_kib\": %ld, \"invalid_samples\": %llu}\n",
          image.width, image.height, stats.samples_per_pixel, static_cast<unsigned long long>(stats.camera_rays),
          session.ranks(), stats.threads, seed,
          used.integrator == IntegratorType::direct ? "direct"
          : used.integrator == IntegratorType::path ? "path"
          : used.integrator == IntegratorType::photon ? "photon"
          : used.integrator == IntegratorType::sppm ? "sppm" : "bdpt",
          used.max_depth,
          used.mis ? "true" : "false", used.light_samples, name_of(used.light_strategy), used.russian_roulette ? "true" : "false",
          used.russian_roulette_depth, stats.seconds, render_cpu_seconds, busiest_rank_cpu_seconds, process_cpu_seconds,
          static_cast<unsigned long long>(stats.camera_rays), static_cast<unsigned long long>(stats.extension_rays),
          static_cast<unsigned long long>(stats.shadow_rays), static_cast<unsigned long long>(stats.total_rays()),
          rays_per_second, stats.seconds > 0 ? static_cast<double>(stats.camera_rays) / stats.seconds : 0.0,
          render_cpu_seconds > 0 ? static_cast<double>(stats.total_rays()) / render_cpu_seconds : 0.0,
          usage.ru_maxrss, static_cast<unsigned long long>(stats.invalid_samples));
    }
  } catch (const std::bad_alloc&) {
    return session.report_error(std::runtime_error(out_of_memory_message(doing)));
  } catch (const std::exception& error) {  // a PbrtImportError's text is a whole diagnostic, printed as it is
    return session.report_error(error);
  }
  return 0;
}
