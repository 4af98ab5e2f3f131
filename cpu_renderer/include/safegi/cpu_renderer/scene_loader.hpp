// Reads a scene file (docs/scene-format.md) into a Scene, converting every
// value to reference units once and checking every field's dimension.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// What a malformed scene throws; what() is the whole message, starting with
// the file name: "box.json: lights[0].power: expected power (e.g. W), got \"3 m\" (length)".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads an image file (a texture, an environment map) as RGB floats, row 0 at
// the top, 8-bit values scaled to [0, 1]; throws a std::exception whose what()
// says why it cannot.
using ImageFileReader = std::function<Image(const std::filesystem::path&)>;

struct SceneLoadOptions {
  // How image files are read. Empty: PFM only (the core links no OpenImageIO);
  // the programs pass read_image (image_io.hpp), which reads any format.
  ImageFileReader read_image;
};

Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

// Reads an image file with `reader` (empty: PFM files only) and checks that it
// has pixels, every value finite and non-negative; throws std::runtime_error
// saying why not, without the file's name (the caller's message names it).
// Both scene readers (JSON and pbrt) read their textures and maps through it.
Image read_checked_image(const std::filesystem::path& file, const ImageFileReader& reader);

// `display_name` starts error messages; relative mesh and image paths resolve against `base_directory`.
Scene parse_scene(std::string_view json_text, std::string_view display_name,
                  const std::filesystem::path& base_directory, const SceneLoadOptions& options = {});

}  // namespace safegi::render
