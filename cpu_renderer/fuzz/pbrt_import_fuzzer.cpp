// libFuzzer target over the pbrt-v3 importer: tokenizer, parser, importer and
// the rendering of its diagnostics. Included files, PLY meshes and images come
// from a fixed in-memory set (one each, valid), so the fuzzer never reads the disk.
// Any crash, sanitizer report, hang, or an exception other than
// PbrtImportError is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "safegi/cpu_renderer/pbrt_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kInclude = "Shape \"sphere\" \"float radius\" [0.5]\n";
  static const std::string kPly =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  safegi::render::PbrtImportOptions options;
  options.metres_per_unit = 0.01;
  options.read_file = [](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
    if (path.filename() == "inc.pbrt") return kInclude;
    if (path.filename() == "mesh.ply") return kPly;
    error = "no such file";
    return std::nullopt;
  };
  // Any image name with a format pbrt-v3 reads: a 2×2 image of values above 1
  // (so that reflectance checks fire too), except "missing.*".
  options.read_image = [](const std::filesystem::path& path) {
    if (path.stem() == "missing") throw std::runtime_error("no such file");
    safegi::render::Image image;
    image.width = image.height = 2;
    image.rgb = {0.1f, 0.2f, 0.3f, 0.5f, 0.5f, 0.5f, 0.9f, 0.8f, 0.7f, 2.0f, 0.0f, 1.0f};
    return image;
  };
  try {
    safegi::render::PbrtScene scene =
        safegi::render::parse_pbrt_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pbrt", "dir", options);
    (void)scene;
  } catch (const safegi::render::PbrtImportError&) {
  }
  return 0;
}
