// safegi-preview (typed) and safegi-preview-unchecked: the GL preview of a
// scene file, written as EXR (linear) and PNG (sRGB). One source, two builds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <ctime>
#include <vector>

#include <CLI/CLI.hpp>
#include <safegi/diagnostics/command_line.hpp>
#include <safegi/runtime_gl/context.hpp>

#include "safegi/cpu_renderer/image_io.hpp"
#include "safegi/cpu_renderer/memory_estimate.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"
#include "safegi/preview/preview.hpp"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// CPU time of the whole process (llvmpipe's rasterizer threads included): on a
// shared, loaded machine it says what a frame costs, where wall time says how
// much of the machine the process got.
double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const Clock::time_point start = Clock::now();
  CLI::App app{"SafeGI GL preview: direct illumination of a scene file (docs/preview.md) to EXR and PNG",
               std::filesystem::path(argv[0]).filename().string()};
  std::string scene_file, output = "preview.exr", resolution, platform, length_unit;
  safegi::preview::PreviewOptions options;
  int time_samples = 0, frames = 1;
  bool no_area_shadows = false, stats = false, pfm = false;
  app.add_option("scene", scene_file, "scene file (.json, docs/scene-format.md; or a pbrt-v3 .pbrt)")->required();
  app.add_option("--length-unit", length_unit, "what one pbrt length unit is (m, cm, mm, in, ...; .pbrt scenes only)");
  app.add_option("-o,--output", output, "NAME.exr: writes NAME.exr (linear) and NAME.png (sRGB); NAME.png: PNG only");
  app.add_option("--light-samples", options.light_samples, "points per area light per pass (default 16)")
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--time-samples", time_samples,
                 "passes accumulated over the shutter, each at its own sub-pixel offset (default: 16 with a shutter, "
                 "else 1)")
      ->check(CLI::Range(1, 1 << 12));
  app.add_option("--resolution", resolution, "image size WIDTHxHEIGHT (default: the scene's)");
  app.add_option("--platform", platform, "GL platform: auto, egl, egl-device, egl-surfaceless, osmesa "
                                         "(default: $SAFEGI_GL_PLATFORM, else auto)");
  app.add_option("--shadow-resolution", options.shadow_resolution, "texels along a point light's cube face (512)")
      ->check(CLI::Range(1, 8192));
  app.add_option("--area-shadow-resolution", options.area_shadow_resolution,
                 "texels along the cube face of an area-light sample (256)")
      ->check(CLI::Range(1, 8192));
  app.add_option("--shadow-bias", options.shadow_bias_texels, "shadow bias in texel footprints (1.5)")
      ->check(CLI::Range(0.0f, 100.0f));
  app.add_flag("--no-area-shadows", no_area_shadows, "area-light samples cast no shadows (faster)");
  app.add_flag("--spirv", options.spirv_shaders,
               "load the shaders as SPIR-V (glslang, OpenGL target) through GL_ARB_gl_spirv instead of GLSL");
  app.add_flag("--refresh-shadows", options.refresh_shadows,
               "redraw point-light shadow maps every frame even when nothing moves (timing)");
  app.add_option("--frames", frames, "render the frame this many times (timing; the last one is written)")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--pfm", pfm, "also write NAME.pfm (exact floats, readable without OpenImageIO)");
  app.add_flag("--stats", stats, "timings on stderr: start-up phases, first frame, median frame");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return safegi::exit_after_parse_error(app, error);
  }

  try {
    std::filesystem::path out(output);
    if (out.extension() != ".exr" && out.extension() != ".png")
      throw safegi::render::CommandLineError("-o: expected a name ending in .exr or .png, got '" + output + "'");
    safegi::render::Scene scene;
    if (std::filesystem::path(scene_file).extension() == ".pbrt") {
      if (length_unit.empty())
        throw safegi::render::CommandLineError(scene_file + ": pbrt scenes carry no units: say what one pbrt length "
                                               "unit is with --length-unit (m, cm, mm, in, ...)");
      safegi::render::PbrtScene imported = safegi::render::load_pbrt_scene(
          scene_file, {safegi::render::parse_length_unit(length_unit), {}, safegi::render::read_image});
      std::cerr << imported.warnings;
      scene = std::move(imported.scene);
    } else {
      if (!length_unit.empty())
        throw safegi::render::CommandLineError("--length-unit: only for pbrt scenes (JSON scenes carry units)");
      scene = safegi::render::load_scene(scene_file, safegi::render::SceneLoadOptions{safegi::render::read_image});
    }
    if (scene.has_media()) {
      std::cerr << "warning: the preview draws no participating media and no invisible surfaces: previewing the "
                   "scene without them\n";
      scene.drop_media();
    }
    if (!resolution.empty()) {
      const safegi::render::ImageSize size = safegi::render::parse_resolution(resolution);
      options.width = size.width;
      options.height = size.height;
    }
    bool shutter = scene.camera.shutter_close > scene.camera.shutter_open;
    options.passes = time_samples > 0 ? time_samples : (shutter ? 16 : 1);
    options.area_shadows = !no_area_shadows;
    const double loaded = seconds_since(start);

    safegi::gl::ContextOptions context_options;
    if (!platform.empty()) context_options.platform = safegi::gl::platform_from_string(platform);
    safegi::gl::Context context(context_options);
    const double context_ready = seconds_since(start);

    safegi::preview::Preview preview(scene, options);  // compiles the annotated shaders through safegi::compile
    const double programs_ready = seconds_since(start);

    std::vector<double> frame_seconds, frame_cpu_seconds;
    safegi::render::Image image;
    safegi::preview::FrameStats frame_stats;
    double first_frame = 0;
    for (int f = 0; f < frames; ++f) {
      Clock::time_point frame_start = Clock::now();
      double cpu_start = process_cpu_seconds();
      image = preview.render(&frame_stats);  // read back included: a frame is done when its pixels are
      frame_seconds.push_back(seconds_since(frame_start));
      frame_cpu_seconds.push_back(process_cpu_seconds() - cpu_start);
      if (f == 0) first_frame = seconds_since(start);
    }
    // What the preview does not model (curved mirrors, glass, ...): said on
    // stderr and in the image files.
    std::string note;
    for (const std::string& phrase : preview.approximations()) {
      note += (note.empty() ? "SafeGI preview: " : "; ") + phrase;
      std::fprintf(stderr, "warning: preview: %s\n", phrase.c_str());
    }
    if (out.extension() == ".exr") {
      safegi::render::write_exr(out, image, note);
      safegi::render::write_png(std::filesystem::path(out).replace_extension(".png"), image, note);
    } else {
      safegi::render::write_png(out, image, note);
    }
    if (pfm) safegi::render::write_pfm(std::filesystem::path(out).replace_extension(".pfm"), image);
    if (stats) {
      std::vector<double> sorted = frame_seconds;
      std::sort(sorted.begin(), sorted.end());
      double wall = median(frame_seconds), cpu = median(frame_cpu_seconds);
      std::fprintf(stderr,
                   "%s\n%dx%d, %d passes, %d area samples, %d shadow faces, %d draws per frame\n"
                   "start-up: scene %.3f s, context %.3f s, shaders compiled and linked %.3f s, first frame at %.3f s\n"
                   "frames: %d, median %.2f ms (%.1f fps), min %.2f ms, max %.2f ms; process CPU time per frame: median %.2f ms\n",
                   safegi::gl::describe(context.info()).c_str(), preview.width(), preview.height(),
                   frame_stats.passes, frame_stats.area_samples, frame_stats.shadow_faces, frame_stats.draw_calls,
                   loaded, context_ready - loaded, programs_ready - context_ready, first_frame, frames,
                   wall * 1e3, 1.0 / wall, sorted.front() * 1e3, sorted.back() * 1e3, cpu * 1e3);
    }
  } catch (const std::bad_alloc&) {
    std::cerr << safegi::error_report(safegi::render::out_of_memory_message("previewing the scene"));
    return safegi::kExitInputError;
  } catch (const safegi::render::CommandLineError& error) {
    std::cerr << safegi::error_report(error.what());
    return safegi::kExitUsage;
  } catch (const std::exception& error) {  // a PbrtImportError's text is a whole diagnostic, printed as it is
    std::cerr << safegi::error_report(error.what());
    return safegi::kExitInputError;
  }
  return 0;
}
