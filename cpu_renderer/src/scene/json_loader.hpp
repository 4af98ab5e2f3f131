// The JSON scene reader (docs/scene-format.md), in the parts the pbrt reader
// also has: field readers that check every value's dimension against the type
// it is stored in (json_fields.cpp), textures and materials
// (json_materials.cpp), shapes and meshes (json_shapes.cpp); scene_loader.cpp
// reads the document's top level, render settings, camera, transforms and lights.
#pragma once

#include <array>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"
#include "safegi/cpu_renderer/unit_expression.hpp"

namespace safegi::render::json {

using Json = nlohmann::json;
using Triple = std::array<double, 3>;

// The run-time twin of a compile-time dimension, so that a field's expected
// unit is derived from the type it is stored in (both name the bases of
// vocabulary.def; `proj` is left out, as scene files never write it).
template <class Term>
void add_term(RuntimeDimension& dimension) {
  dimension = runtime_dim::with_base_power(dimension, Term::base::name.view(), Term::exponent);
}
template <class... Terms>
RuntimeDimension runtime_dimension(dimension<Terms...>) {
  RuntimeDimension result;
  (add_term<Terms>(result), ...);
  return result;
}
template <class D>
RuntimeDimension runtime_dimension_of() {
  return runtime_dimension(D{});
}

inline sg::vec3_rep to_vec3(const Triple& t) {
  return {static_cast<Real>(t[0]), static_cast<Real>(t[1]), static_cast<Real>(t[2])};
}

// Where a value sits in the document, spelled as in error messages: shapes[2].radius.
class JsonPath {
 public:
  JsonPath() = default;
  JsonPath field(std::string_view name) const {
    return JsonPath(text_.empty() ? std::string(name) : text_ + "." + std::string(name));
  }
  JsonPath index(size_t i) const { return JsonPath(text_ + "[" + std::to_string(i) + "]"); }
  const std::string& text() const { return text_; }

 private:
  explicit JsonPath(std::string text) : text_(std::move(text)) {}
  std::string text_;
};

// A value as error messages quote it: at most 60 characters.
std::string short_dump(const Json& value);

// Reading one field: its JSON value, where it sits (for messages), what it must be.
class JsonFields {
 public:
  explicit JsonFields(std::string_view display_name) : display_name_(display_name) {}

  [[noreturn]] void fail(const JsonPath& path, const std::string& message) const;

  const Json& object(const Json& value, const JsonPath& path, std::initializer_list<std::string_view> allowed);

  const Json& required(const Json& parent, const JsonPath& path, const char* name);

  // Every value ends up in a Real (float, or double in the double build): one
  // that would become infinite, or 0 from a non-zero value, is an error rather
  // than a silently broken scene.
  void require_float_range(const JsonPath& path, double value) const;

  // A dimensioned scalar: "5 mm", {"value": 5, "unit": "mm"}, or a bare number
  // when the field is dimensionless.
  double scalar(const Json& value, const JsonPath& path, const RuntimeDimension& expected);

  Unit parse_unit_field(const Json& value, const JsonPath& path);

  // Three components: {"value": [x, y, z], "unit": "m"}, ["1 m", "2 m", "3 m"],
  // or [x, y, z] when dimensionless.
  Triple triple(const Json& value, const JsonPath& path, const RuntimeDimension& expected);

  // An RGB spectrum: a triple, or one scalar for grey.
  struct Rgb {
    Real r, g, b;
  };
  Rgb rgb_field(const Json& value, const JsonPath& path, const RuntimeDimension& expected);

  Reflectance reflectance(const Json& value, const JsonPath& path);

  int integer(const Json& value, const JsonPath& path, int minimum, int maximum);

  std::string string(const Json& value, const JsonPath& path);

  bool boolean(const Json& value, const JsonPath& path);

  // Typed fields: the expected dimension comes from the type the value is stored in.
  template <class D>
  quantity<D> typed_scalar(const Json& value, const JsonPath& path) {
    return sg::from_raw<quantity<D>>(static_cast<Real>(scalar(value, path, runtime_dimension_of<D>())));
  }
  template <class D>
  sg::spectrum<D> typed_spectrum(const Json& value, const JsonPath& path) {
    Rgb rgb = rgb_field(value, path, runtime_dimension_of<D>());
    return sg::from_raw<sg::spectrum<D>>(sg::vec3_rep(rgb.r, rgb.g, rgb.b));
  }
  template <class P>
  P typed_point(const Json& value, const JsonPath& path) {
    return sg::from_raw<P>(to_vec3(triple(value, path, runtime_dim::length)));
  }

  // A number without unit, in [minimum, maximum].
  Real number(const Json& value, const JsonPath& path, double minimum, double maximum);
  static std::string short_number(double v);

 protected:
  std::string display_name_;
};

class Loader : public JsonFields {
 public:
  Loader(std::string_view display_name, std::filesystem::path base_directory, const SceneLoadOptions& options)
      : JsonFields(display_name), base_directory_(std::move(base_directory)), options_(options) {}

  Scene load(const Json& root);

 private:
  void load_render_settings(const Json& value, const JsonPath& path, RenderSettings& settings);
  CameraProjection projection(const Json& value, const JsonPath& path);
  PixelFilter pixel_filter(const Json& value, const JsonPath& path);
  void load_camera(const Json& value, const JsonPath& path, Camera& camera);
  Image read_image_file(const Json& file_value, const JsonPath& path, std::string& file);
  ImageTexture load_texture(const std::string& name, const Json& value, const JsonPath& path);
  // A reflectance that may be textured: a number, RGB triple or {"texture": name}.
  TexturedReflectance textured_reflectance(const Json& value, const JsonPath& path);
  Material load_material(const std::string& name, const Json& value, const JsonPath& path);
  // A mix's parts, by name (any order in the file); a mix that contains itself is an error.
  void resolve_mix(Scene& scene, int index, const Json& value, const JsonPath& path,
                   const std::map<std::string, int>& material_index);
  // A conductor's η (`zero_allowed` false: above 0) or k (at least 0), at most 1000, grey or RGB.
  IndexSpectrum index_spectrum(const Json& value, const JsonPath& path, bool zero_allowed);
  // The diffuse reflectance's largest value in each channel, texture included.
  Reflectance largest_diffuse(const TexturedReflectance& diffuse) const;
  Shape load_shape(const Json& value, const JsonPath& path, const std::map<std::string, int>& materials);
  void load_mesh_file(const Json& value, const JsonPath& path, Shape& shape);
  void load_ply_file(const std::filesystem::path& full, const std::string& file, Real scale, const JsonPath& path,
                     Shape& shape);
  void load_triangles(const Json& value, const JsonPath& path, Shape& shape);
  RenderFromObject load_transform(const Json& value, const JsonPath& path);
  void load_light(const Json& value, const JsonPath& path, Scene& scene);
  EnvironmentLight load_environment(const Json& value, const JsonPath& path);
  IntensityMap load_intensity_map(const Json& value, const JsonPath& path);
  RenderFromLight load_rotation(const Json& value, const JsonPath& path, const std::string& what);

  std::filesystem::path base_directory_;
  const SceneLoadOptions& options_;
  std::map<std::string, int> texture_index_;
  std::vector<const MipMap*> textures_;  // by index, for checks
};

}  // namespace safegi::render::json
