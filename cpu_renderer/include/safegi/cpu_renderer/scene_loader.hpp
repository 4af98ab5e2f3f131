// Reads a scene file (docs/scene-format.md) into a Scene, converting every
// value to reference units once and checking every field's dimension.
#pragma once

#include <filesystem>
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

Scene load_scene(const std::filesystem::path& file);

// `display_name` starts error messages; relative mesh paths resolve against `base_directory`.
Scene parse_scene(std::string_view json_text, std::string_view display_name,
                  const std::filesystem::path& base_directory);

}  // namespace safegi::render
