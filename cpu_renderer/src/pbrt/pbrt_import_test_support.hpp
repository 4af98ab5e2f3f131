// What the pbrt import tests share: scenes from text with an in-memory file
// system, the smallest world around some directives, the users that make a
// material or texture count, and typed views of a material's parameters.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <variant>

#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render::pbrt_test {

// A file system in memory: Include and plymesh read from it, never from disk.
inline PbrtImportOptions in_memory(std::map<std::string, std::string> files = {}, double metres = 1) {
  PbrtImportOptions options;
  options.metres_per_unit = metres;
  options.read_file = [files](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
    auto found = files.find(path.lexically_normal().string());
    if (found == files.end()) {
      error = "no such file";
      return std::nullopt;
    }
    return found->second;
  };
  return options;
}

// A material's parameters, as the test expects its type to be (a failed
// expectation, and default parameters, when it is another).
template <class Parameters>
bool is(const Material& material) {
  return std::holds_alternative<Parameters>(material.model);
}
template <class Parameters>
Parameters as(const Material& material) {
  EXPECT_TRUE(is<Parameters>(material)) << material.name;
  return is<Parameters>(material) ? std::get<Parameters>(material.model) : Parameters{};
}
inline TexturedReflectance diffuse(const Material& material) {
  EXPECT_TRUE(diffuse_of(material)) << material.name << " has no diffuse part";
  return diffuse_of(material) ? *diffuse_of(material) : TexturedReflectance{};
}

// pbrt-v3's RoughnessToAlpha, written out for the expected values.
inline double pbrt_alpha(double roughness) {
  double x = std::log(roughness);
  return 1.62142 + 0.819955 * x + 0.1734 * x * x + 0.0171201 * x * x * x + 0.000640711 * x * x * x * x;
}

inline PbrtScene import(const std::string& text, const PbrtImportOptions& options = in_memory()) {
  return parse_pbrt_scene(text, "scene.pbrt", "dir", options);
}

inline std::string import_error(const std::string& text, const PbrtImportOptions& options = in_memory()) {
  try {
    import(text, options);
  } catch (const PbrtImportError& error) {
    return error.what();
  }
  return "(no error)";
}

inline std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// The smallest complete scene around some world-block text.
inline std::string world(const std::string& body) { return "WorldBegin\n" + body + "\nWorldEnd\n"; }

// A material is made (and its errors reported) only for the shapes that use
// it, a texture only for the materials those read: these add the users.
inline std::string used(const std::string& material) { return material + "\nShape \"sphere\""; }
inline std::string used_texture(const std::string& texture) {
  return texture + "\nMaterial \"matte\" \"texture Kd\" \"t\"\nShape \"sphere\"";
}
inline std::string used_float_texture(const std::string& texture) {
  return texture + "\nMaterial \"plastic\" \"texture roughness\" \"t\"\nShape \"sphere\"";
}

}  // namespace safegi::render::pbrt_test
