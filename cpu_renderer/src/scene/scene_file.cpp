#include <filesystem>

#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {

PbrtScene read_scene_file(const std::string& path, const std::string& length_unit, const ImageFileReader& read_image) {
  if (std::filesystem::path(path).extension() != ".pbrt") {
    if (!length_unit.empty()) throw CommandLineError("--length-unit: only for pbrt scenes (JSON scenes carry units)");
    PbrtScene json;
    json.scene = load_scene(path, SceneLoadOptions{read_image});
    return json;
  }
  if (length_unit.empty())
    throw CommandLineError(path + ": pbrt scenes carry no units: say what one pbrt length unit is "
                                  "with --length-unit (m, cm, mm, in, ...)");
  double metres_per_unit = 0;
  try {
    metres_per_unit = parse_length_unit(length_unit);
  } catch (const SceneError& error) {
    throw CommandLineError(error.what());
  }
  return load_pbrt_scene(path, {metres_per_unit, {}, read_image});
}

}  // namespace safegi::render
