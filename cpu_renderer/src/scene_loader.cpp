#include "safegi/cpu_renderer/scene_loader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <tiny_obj_loader.h>

#include "ply.hpp"
#include "printable.hpp"
#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/unit_expression.hpp"

namespace safegi::render {

namespace {

using Json = nlohmann::json;
using Triple = std::array<double, 3>;

// The run-time twin of a compile-time dimension, so that a field's expected
// unit is derived from the type it is stored in. `proj` is internal
// bookkeeping for the cosine and never written in a scene file.
template <class Term>
void add_term(RuntimeDimension& dimension) {
  constexpr std::string_view name = Term::base::name.view();
  constexpr std::pair<std::string_view, Base> kBases[] = {
      {"length", Base::length}, {"time", Base::time}, {"energy", Base::energy},
      {"angle", Base::angle},   {"solid_angle", Base::solid_angle}};
  for (const auto& [base_name, base] : kBases)
    if (name == base_name) dimension.exponents[static_cast<int>(base)] += Term::exponent;
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

sg::vec3_rep to_vec3(const Triple& t) {
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

std::string short_dump(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

class Loader {
 public:
  Loader(std::string_view display_name, std::filesystem::path base_directory, const SceneLoadOptions& options)
      : display_name_(display_name), base_directory_(std::move(base_directory)), options_(options) {}

  Scene load(const Json& root);

 private:
  [[noreturn]] void fail(const JsonPath& path, const std::string& message) const {
    std::string where = path.text().empty() ? "" : path.text() + ": ";
    throw SceneError(display_name_ + ": " + where + message);
  }

  const Json& object(const Json& value, const JsonPath& path, std::initializer_list<std::string_view> allowed) {
    if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
    for (const auto& [key, member] : value.items()) {
      bool known = false;
      for (std::string_view name : allowed) known = known || key == name;
      if (!known) {
        std::string list;
        for (std::string_view name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
        fail(path.field(key), "unknown field (expected one of: " + list + ")");
      }
    }
    return value;
  }

  const Json& required(const Json& parent, const JsonPath& path, const char* name) {
    auto found = parent.find(name);
    if (found == parent.end()) fail(path, std::string("missing field '") + name + "'");
    return *found;
  }

  // Every value ends up in a Real (float, or double in the double build): one
  // that would become infinite, or 0 from a non-zero value, is an error rather
  // than a silently broken scene.
  void require_float_range(const JsonPath& path, double value) const {
    if (!std::isfinite(value)) fail(path, "value is not finite");
    Real stored = static_cast<Real>(value);
    if (std::isinf(stored) || (stored == 0 && value != 0))
      fail(path, sizeof(Real) == 4
                     ? "value is out of float range (in SI units its magnitude must be 0 or lie in 1.4e-45 .. 3.4e38)"
                     : "value is out of double range (in SI units its magnitude must be 0 or lie in 4.9e-324 .. 1.8e308)");
  }

  // A dimensioned scalar: "5 mm", {"value": 5, "unit": "mm"}, or a bare number
  // when the field is dimensionless.
  double scalar(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
    Quantity quantity;
    if (value.is_number()) {
      if (!expected.dimensionless())
        fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (a number without unit)");
      quantity = {value.get<double>(), {}};
    } else if (value.is_string()) {
      std::string error;
      std::optional<Quantity> parsed = parse_quantity(value.get<std::string>(), error);
      if (!parsed) fail(path, "cannot read " + short_dump(value) + ": " + error);
      quantity = *parsed;
    } else if (value.is_object() && value.contains("value") && value["value"].is_number()) {
      object(value, path, {"value", "unit"});
      Unit unit = parse_unit_field(value, path);
      quantity = {value["value"].get<double>() * unit.to_reference, unit.dimension};
    } else {
      fail(path, "expected " + describe(expected) + ", got " + short_dump(value));
    }
    if (!(quantity.dimension == expected))
      fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (" +
                     dimension_name(quantity.dimension) + ")");
    require_float_range(path, quantity.value);
    return quantity.value;
  }

  Unit parse_unit_field(const Json& value, const JsonPath& path) {
    if (!value.contains("unit")) return Unit{};
    const Json& unit_json = value["unit"];
    if (!unit_json.is_string()) fail(path.field("unit"), "expected a unit string, got " + short_dump(unit_json));
    std::string error;
    std::optional<Unit> unit = parse_unit(unit_json.get<std::string>(), error);
    if (!unit) fail(path.field("unit"), "cannot read " + short_dump(unit_json) + ": " + error);
    return *unit;
  }

  // Three components: {"value": [x, y, z], "unit": "m"}, ["1 m", "2 m", "3 m"],
  // or [x, y, z] when dimensionless.
  Triple triple(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
    if (value.is_object() && value.contains("value") && value["value"].is_array()) {
      object(value, path, {"value", "unit"});
      const Json& components = value["value"];
      if (components.size() != 3) fail(path.field("value"), "expected 3 numbers, got " + short_dump(components));
      Unit unit = parse_unit_field(value, path);
      if (!(unit.dimension == expected))
        fail(path, "expected " + describe(expected) + ", got " + short_dump(value) + " (" +
                       dimension_name(unit.dimension) + ")");
      Triple result;
      for (size_t i = 0; i < 3; ++i) {
        if (!components[i].is_number())
          fail(path.field("value").index(i), "expected a number, got " + short_dump(components[i]));
        result[i] = components[i].get<double>() * unit.to_reference;
        require_float_range(path.field("value").index(i), result[i]);
      }
      return result;
    }
    if (value.is_array()) {
      if (value.size() != 3) fail(path, "expected 3 components, got " + short_dump(value));
      Triple result;
      for (size_t i = 0; i < 3; ++i) result[i] = scalar(value[i], path.index(i), expected);
      return result;
    }
    fail(path, "expected 3 components of " + describe(expected) + ", got " + short_dump(value));
  }

  // An RGB spectrum: a triple, or one scalar for grey.
  struct Rgb {
    Real r, g, b;
  };
  Rgb rgb_field(const Json& value, const JsonPath& path, const RuntimeDimension& expected) {
    bool is_triple = value.is_array() || (value.is_object() && value.contains("value") && value["value"].is_array());
    if (!is_triple) {
      Real grey = static_cast<Real>(scalar(value, path, expected));
      return {grey, grey, grey};
    }
    Triple t = triple(value, path, expected);
    return {static_cast<Real>(t[0]), static_cast<Real>(t[1]), static_cast<Real>(t[2])};
  }

  Reflectance reflectance(const Json& value, const JsonPath& path) {
    Reflectance albedo = typed_spectrum<dim::dimensionless>(value, path);
    for (int c = 0; c < 3; ++c)
      if (albedo[c] < 0 || albedo[c] > 1) fail(path, "reflectance must lie in [0, 1], got " + short_dump(value));
    return albedo;
  }

  int integer(const Json& value, const JsonPath& path, int minimum, int maximum) {
    if (!value.is_number_integer() || value.get<long long>() < minimum || value.get<long long>() > maximum)
      fail(path, "expected an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
                     "], got " + short_dump(value));
    return value.get<int>();
  }

  std::string string(const Json& value, const JsonPath& path) {
    if (!value.is_string()) fail(path, "expected a string, got " + short_dump(value));
    return value.get<std::string>();
  }

  bool boolean(const Json& value, const JsonPath& path) {
    if (!value.is_boolean()) fail(path, "expected true or false, got " + short_dump(value));
    return value.get<bool>();
  }

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
  Real number(const Json& value, const JsonPath& path, double minimum, double maximum) {
    double v = scalar(value, path, runtime_dim::none);
    if (!(v >= minimum && v <= maximum))
      fail(path, "expected a number in [" + short_number(minimum) + ", " + short_number(maximum) + "], got " +
                     short_dump(value));
    return static_cast<Real>(v);
  }
  static std::string short_number(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  }

  void load_render_settings(const Json& value, const JsonPath& path, RenderSettings& settings);
  void load_camera(const Json& value, const JsonPath& path, Camera& camera);
  Image read_image_file(const Json& file_value, const JsonPath& path, std::string& file);
  ImageTexture load_texture(const std::string& name, const Json& value, const JsonPath& path);
  // A reflectance that may be textured: a number, RGB triple or {"texture": name}.
  Reflectance textured_reflectance(const Json& value, const JsonPath& path, int& texture);
  Material load_material(const std::string& name, const Json& value, const JsonPath& path);
  // The diffuse reflectance's largest value in each channel, texture included.
  Reflectance largest_diffuse(const Material& material) const {
    return material.diffuse_texture < 0 ? material.diffuse
                                        : material.diffuse * textures_[material.diffuse_texture]->maximum();
  }
  Shape load_shape(const Json& value, const JsonPath& path, const std::map<std::string, int>& materials);
  void load_mesh_file(const Json& value, const JsonPath& path, Shape& shape);
  void load_ply_file(const std::filesystem::path& full, const std::string& file, Real scale, const JsonPath& path,
                     Shape& shape);
  void load_triangles(const Json& value, const JsonPath& path, Shape& shape);
  ObjectToWorld load_transform(const Json& value, const JsonPath& path);
  void load_light(const Json& value, const JsonPath& path, Scene& scene);
  EnvironmentLight load_environment(const Json& value, const JsonPath& path);

  std::string display_name_;
  std::filesystem::path base_directory_;
  const SceneLoadOptions& options_;
  std::map<std::string, int> texture_index_;
  std::vector<const MipMap*> textures_;  // by index, for checks
};

Scene Loader::load(const Json& root) {
  JsonPath top;
  object(root, top, {"format", "description", "render", "camera", "textures", "materials", "shapes", "lights"});
  if (root.contains("format") && root["format"] != "safegi-scene/1")
    fail(top.field("format"), "expected \"safegi-scene/1\", got " + short_dump(root["format"]));
  Scene scene;
  if (root.contains("render")) load_render_settings(root["render"], top.field("render"), scene.settings);
  load_camera(required(root, top, "camera"), top.field("camera"), scene.camera);

  if (root.contains("textures")) {
    const Json& textures = root["textures"];
    if (!textures.is_object()) fail(top.field("textures"), "expected an object of named textures");
    for (const auto& [name, value] : textures.items()) {
      texture_index_[name] = static_cast<int>(scene.textures.size());
      scene.textures.push_back(load_texture(name, value, top.field("textures").field(name)));
      textures_.push_back(scene.textures.back().mipmap.get());
    }
  }
  std::map<std::string, int> material_index;
  if (root.contains("materials")) {
    const Json& materials = root["materials"];
    if (!materials.is_object()) fail(top.field("materials"), "expected an object of named materials");
    for (const auto& [name, value] : materials.items()) {
      material_index[name] = static_cast<int>(scene.materials.size());
      scene.materials.push_back(load_material(name, value, top.field("materials").field(name)));
    }
  }
  if (root.contains("shapes")) {
    const Json& shapes = root["shapes"];
    if (!shapes.is_array()) fail(top.field("shapes"), "expected an array, got " + short_dump(shapes));
    for (size_t i = 0; i < shapes.size(); ++i)
      scene.shapes.push_back(load_shape(shapes[i], top.field("shapes").index(i), material_index));
  }
  if (root.contains("lights")) {
    const Json& lights = root["lights"];
    if (!lights.is_array()) fail(top.field("lights"), "expected an array, got " + short_dump(lights));
    for (size_t i = 0; i < lights.size(); ++i) {
      JsonPath light_path = top.field("lights").index(i);
      if (lights[i].is_object() && lights[i].contains("type") && lights[i]["type"] == "environment") {
        if (scene.environment) fail(light_path, "a scene has at most one environment light");
        scene.environment = load_environment(lights[i], light_path);
      } else {
        load_light(lights[i], light_path, scene);
      }
    }
  }
  return scene;
}

void Loader::load_render_settings(const Json& value, const JsonPath& path, RenderSettings& settings) {
  object(value, path,
         {"resolution", "spp", "integrator", "max_depth", "mis", "light_samples", "russian_roulette",
          "russian_roulette_depth", "photons", "photon_radius"});
  if (value.contains("resolution")) {
    const Json& resolution = value["resolution"];
    if (!resolution.is_array() || resolution.size() != 2)
      fail(path.field("resolution"), "expected [width, height], got " + short_dump(resolution));
    settings.width = integer(resolution[0], path.field("resolution").index(0), 1, kMaxImageSide);
    settings.height = integer(resolution[1], path.field("resolution").index(1), 1, kMaxImageSide);
  }
  if (value.contains("spp")) settings.spp = integer(value["spp"], path.field("spp"), 1, 1 << 24);
  if (value.contains("max_depth")) settings.max_depth = integer(value["max_depth"], path.field("max_depth"), 1, 1024);
  if (value.contains("integrator")) {
    std::string name = string(value["integrator"], path.field("integrator"));
    if (name == "direct") settings.integrator = IntegratorType::direct;
    else if (name == "path") settings.integrator = IntegratorType::path;
    else if (name == "photon") settings.integrator = IntegratorType::photon;
    else fail(path.field("integrator"), "expected \"direct\", \"path\" or \"photon\", got " + short_dump(value["integrator"]));
  }
  if (value.contains("mis")) settings.mis = boolean(value["mis"], path.field("mis"));
  if (value.contains("light_samples"))
    settings.light_samples = integer(value["light_samples"], path.field("light_samples"), 1, 1024);
  if (value.contains("russian_roulette"))
    settings.russian_roulette = boolean(value["russian_roulette"], path.field("russian_roulette"));
  if (value.contains("russian_roulette_depth"))
    settings.russian_roulette_depth =
        integer(value["russian_roulette_depth"], path.field("russian_roulette_depth"), 0, 1024);
  if (value.contains("photons")) settings.photons = integer(value["photons"], path.field("photons"), 1, 1 << 28);
  if (value.contains("photon_radius")) {
    settings.photon_radius = typed_scalar<dim::length>(value["photon_radius"], path.field("photon_radius"));
    if (!(settings.photon_radius > sg::zero)) fail(path.field("photon_radius"), "must be positive");
  }
}

void Loader::load_camera(const Json& value, const JsonPath& path, Camera& camera) {
  object(value, path, {"position", "look_at", "up", "fov", "lens_radius", "focus_distance", "shutter"});
  camera.position = typed_point<PointWorld>(required(value, path, "position"), path.field("position"));
  camera.look_at = typed_point<PointWorld>(required(value, path, "look_at"), path.field("look_at"));
  Triple up = triple(required(value, path, "up"), path.field("up"), runtime_dim::none);
  Angle fov = typed_scalar<dim::angle>(required(value, path, "fov"), path.field("fov"));
  if (!(fov > Real(0) * units::degree && fov < Real(180) * units::degree))
    fail(path.field("fov"), "expected an angle in (0 deg, 180 deg)");
  camera.fov = fov;
  VectorWorld forward = camera.look_at - camera.position;
  if (!(sg::length(forward) > sg::zero)) fail(path.field("look_at"), "must differ from position");
  sg::vec3_rep up_raw = to_vec3(up);
  if (!(glm::length(glm::cross(sg::raw(forward), up_raw)) > 0))
    fail(path.field("up"), "must not be parallel to the viewing direction");
  camera.up = sg::normalize(sg::from_raw<vector<World, dim::dimensionless>>(up_raw));
  if (value.contains("lens_radius")) {
    camera.lens_radius = typed_scalar<dim::length>(value["lens_radius"], path.field("lens_radius"));
    if (camera.lens_radius < sg::zero) fail(path.field("lens_radius"), "must not be negative");
  }
  camera.focus_distance = sg::length(forward);
  if (value.contains("focus_distance")) {
    camera.focus_distance = typed_scalar<dim::length>(value["focus_distance"], path.field("focus_distance"));
    if (!(camera.focus_distance > sg::zero)) fail(path.field("focus_distance"), "must be positive");
  }
  if (value.contains("shutter")) {
    const Json& shutter = object(value["shutter"], path.field("shutter"), {"open", "close"});
    JsonPath shutter_path = path.field("shutter");
    camera.shutter_open = typed_scalar<dim::time>(required(shutter, shutter_path, "open"), shutter_path.field("open"));
    camera.shutter_close = typed_scalar<dim::time>(required(shutter, shutter_path, "close"), shutter_path.field("close"));
    if (camera.shutter_close < camera.shutter_open) fail(shutter_path, "close must not precede open");
  }
}

Image Loader::read_image_file(const Json& file_value, const JsonPath& path, std::string& file) {
  file = string(file_value, path);
  std::filesystem::path full = base_directory_ / file;
  if (!std::filesystem::is_regular_file(full)) fail(path, "cannot read image '" + file + "': no such file");
  try {
    return read_checked_image(full, options_.read_image);
  } catch (const std::exception& error) {
    fail(path, "cannot read image '" + file + "': " + error.what());
  }
}

ImageTexture Loader::load_texture(const std::string& name, const Json& value, const JsonPath& path) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  if (type != "image") fail(path.field("type"), "expected \"image\", got " + short_dump(value["type"]));
  object(value, path, {"type", "file", "colour_space", "filter", "wrap", "scale", "uv_scale", "uv_offset"});
  ImageTexture texture;
  texture.name = name;
  Image image = read_image_file(required(value, path, "file"), path.field("file"), texture.file);
  // 8-bit images are painted in sRGB; floating-point formats hold linear values.
  std::string extension = std::filesystem::path(texture.file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  bool linear_format = extension == ".exr" || extension == ".hdr" || extension == ".pfm";
  texture.colour_space = linear_format ? ColourSpace::linear : ColourSpace::srgb;
  if (value.contains("colour_space")) {
    std::string space = string(value["colour_space"], path.field("colour_space"));
    if (space == "srgb") texture.colour_space = ColourSpace::srgb;
    else if (space == "linear") texture.colour_space = ColourSpace::linear;
    else fail(path.field("colour_space"), "expected \"srgb\" or \"linear\", got " + short_dump(value["colour_space"]));
  }
  if (value.contains("filter")) {
    std::string filter = string(value["filter"], path.field("filter"));
    if (filter == "bilinear") texture.filter = TextureFilter::bilinear;
    else if (filter == "trilinear") texture.filter = TextureFilter::trilinear;
    else fail(path.field("filter"), "expected \"bilinear\" or \"trilinear\", got " + short_dump(value["filter"]));
  }
  TextureWrap wrap = TextureWrap::repeat;
  if (value.contains("wrap")) {
    std::string mode = string(value["wrap"], path.field("wrap"));
    if (mode == "repeat") wrap = TextureWrap::repeat;
    else if (mode == "clamp") wrap = TextureWrap::clamp;
    else if (mode == "black") wrap = TextureWrap::black;
    else fail(path.field("wrap"), "expected \"repeat\", \"clamp\" or \"black\", got " + short_dump(value["wrap"]));
  }
  if (value.contains("scale")) texture.scale = number(value["scale"], path.field("scale"), 0, 1e6);
  auto pair = [&](const char* field, Real& a, Real& b) {
    if (!value.contains(field)) return;
    const Json& v = value[field];
    if (!v.is_array() || v.size() != 2) fail(path.field(field), "expected [u, v], got " + short_dump(v));
    a = number(v[0], path.field(field).index(0), -1e6, 1e6);
    b = number(v[1], path.field(field).index(1), -1e6, 1e6);
  };
  pair("uv_scale", texture.u_scale, texture.v_scale);
  pair("uv_offset", texture.u_offset, texture.v_offset);
  // Texels are stored as float in every build (8 to 32 bits of data per channel).
  texture.mipmap = std::make_shared<MipMap>(
      to_linear_texels(std::move(image), texture.colour_space, static_cast<float>(texture.scale), true), wrap);
  return texture;
}

Reflectance Loader::textured_reflectance(const Json& value, const JsonPath& path, int& texture) {
  if (value.is_object() && value.contains("texture")) {
    object(value, path, {"texture"});
    std::string name = string(value["texture"], path.field("texture"));
    auto found = texture_index_.find(name);
    if (found == texture_index_.end()) fail(path.field("texture"), "no texture named " + short_dump(value["texture"]));
    texture = found->second;
    if (sg::max_component(textures_[texture]->maximum()) > 1.0f)
      fail(path.field("texture"), "texture " + short_dump(value["texture"]) +
                                      " has values above 1 and cannot be a reflectance (check its scale)");
    return Reflectance(1.0f);
  }
  texture = -1;
  return reflectance(value, path);
}

Material Loader::load_material(const std::string& name, const Json& value, const JsonPath& path) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  Material material;
  material.name = name;
  if (type == "lambert") {
    object(value, path, {"type", "reflectance"});
    material.type = Material::Type::lambert;
    material.diffuse =
        textured_reflectance(required(value, path, "reflectance"), path.field("reflectance"), material.diffuse_texture);
  } else if (type == "phong") {
    object(value, path, {"type", "diffuse", "specular", "exponent"});
    material.type = Material::Type::phong;
    material.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"), material.diffuse_texture);
    material.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    double exponent = scalar(required(value, path, "exponent"), path.field("exponent"), runtime_dim::none);
    if (!(exponent >= 0 && exponent <= 1e6)) fail(path.field("exponent"), "expected a number in [0, 1e6]");
    material.exponent = static_cast<Real>(exponent);
    if (sg::max_component(largest_diffuse(material) + material.specular) > 1.0f)
      fail(path, "diffuse + specular must not exceed 1 in any channel (energy conservation)");
  } else if (type == "mirror") {
    object(value, path, {"type", "reflectance"});
    material.type = Material::Type::mirror;
    material.specular = reflectance(required(value, path, "reflectance"), path.field("reflectance"));
  } else if (type == "glass") {
    object(value, path, {"type", "ior", "reflectance", "transmittance"});
    material.type = Material::Type::glass;
    material.ior = number(required(value, path, "ior"), path.field("ior"), 1.0 / 16, 16);
    material.specular = value.contains("reflectance") ? reflectance(value["reflectance"], path.field("reflectance"))
                                                      : Reflectance(1.0f);
    material.transmission = value.contains("transmittance")
                                ? reflectance(value["transmittance"], path.field("transmittance"))
                                : Reflectance(1.0f);
  } else if (type == "plastic") {
    object(value, path, {"type", "diffuse", "specular", "alpha", "ior", "pbrt_v3_fresnel"});
    material.type = Material::Type::plastic;
    material.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"), material.diffuse_texture);
    material.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    material.alpha = number(required(value, path, "alpha"), path.field("alpha"), 1e-4, 1);
    if (value.contains("ior")) material.ior = number(value["ior"], path.field("ior"), 1, 16);
    if (value.contains("pbrt_v3_fresnel"))
      material.pbrt_v3_plastic_fresnel = boolean(value["pbrt_v3_fresnel"], path.field("pbrt_v3_fresnel"));
    if (sg::max_component(largest_diffuse(material) + material.specular) > 1.0f)
      fail(path, "diffuse + specular must not exceed 1 in any channel (energy conservation)");
  } else {
    fail(path.field("type"), "expected \"lambert\", \"phong\", \"mirror\", \"glass\" or \"plastic\", got " +
                                 short_dump(value["type"]));
  }
  return material;
}

Shape Loader::load_shape(const Json& value, const JsonPath& path, const std::map<std::string, int>& materials) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  static constexpr const char* common[] = {"type", "name", "material", "emission", "two_sided", "transform", "transform_at_close"};
  auto allow = [&](std::initializer_list<const char*> specific) {
    std::vector<std::string_view> names(std::begin(common), std::end(common));
    names.insert(names.end(), specific.begin(), specific.end());
    for (const auto& [key, member] : value.items()) {
      if (std::find(names.begin(), names.end(), key) == names.end()) {
        std::string list;
        for (std::string_view name : names) list += (list.empty() ? "" : ", ") + std::string(name);
        fail(path.field(key), "unknown field (expected one of: " + list + ")");
      }
    }
  };

  Shape shape;
  if (value.contains("name")) shape.name = string(value["name"], path.field("name"));
  if (type == "quad") {
    allow({"origin", "edge_u", "edge_v"});
    shape.type = Shape::Type::mesh;
    auto origin = typed_point<PointObject>(required(value, path, "origin"), path.field("origin"));
    auto u = sg::from_raw<vector<Object>>(to_vec3(triple(required(value, path, "edge_u"), path.field("edge_u"), runtime_dim::length)));
    auto v = sg::from_raw<vector<Object>>(to_vec3(triple(required(value, path, "edge_v"), path.field("edge_v"), runtime_dim::length)));
    if (!(sg::length(sg::cross(u, v)) > sg::zero)) fail(path, "edge_u and edge_v must span a parallelogram");
    shape.positions = {origin, origin + u, origin + u + v, origin + v};
    shape.indices = {0, 1, 2, 0, 2, 3};
    shape.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  } else if (type == "sphere") {
    allow({"center", "radius"});
    shape.type = Shape::Type::sphere;
    shape.center = typed_point<PointObject>(required(value, path, "center"), path.field("center"));
    shape.radius = typed_scalar<dim::length>(required(value, path, "radius"), path.field("radius"));
    if (!(shape.radius > sg::zero)) fail(path.field("radius"), "must be positive");
  } else if (type == "mesh") {
    allow({"file", "unit"});
    load_mesh_file(value, path, shape);
  } else if (type == "triangles") {
    allow({"positions", "indices", "uvs"});
    load_triangles(value, path, shape);
  } else {
    fail(path.field("type"),
         "expected \"quad\", \"sphere\", \"mesh\" or \"triangles\", got " + short_dump(value["type"]));
  }

  if (value.contains("material")) {
    std::string name = string(value["material"], path.field("material"));
    auto found = materials.find(name);
    if (found == materials.end()) fail(path.field("material"), "no material named " + short_dump(value["material"]));
    shape.material = found->second;
  }
  if (value.contains("emission")) {
    Radiance radiance = typed_spectrum<dim::radiance>(value["emission"], path.field("emission"));
    if (radiance.r() < sg::zero || radiance.g() < sg::zero || radiance.b() < sg::zero)
      fail(path.field("emission"), "radiance must not be negative");
    if (!sg::is_black(radiance)) shape.emission = radiance;
  }
  if (value.contains("two_sided")) shape.two_sided_emission = boolean(value["two_sided"], path.field("two_sided"));
  if (value.contains("transform")) shape.render_from_object = load_transform(value["transform"], path.field("transform"));
  if (value.contains("transform_at_close"))
    shape.render_from_object_at_close = load_transform(value["transform_at_close"], path.field("transform_at_close"));
  if (shape.type == Shape::Type::sphere) {
    for (const ObjectToWorld* m : {&shape.render_from_object, shape.render_from_object_at_close ? &*shape.render_from_object_at_close : nullptr}) {
      if (!m) continue;
      sg::mat4_rep forward = sg::raw(*m).forward;
      Real sx = glm::length(sg::vec3_rep(forward[0])), sy = glm::length(sg::vec3_rep(forward[1])), sz = glm::length(sg::vec3_rep(forward[2]));
      if (std::fabs(sx - sy) > 1e-4f * sx || std::fabs(sx - sz) > 1e-4f * sx)
        fail(path.field("transform"), "a sphere's transform must scale uniformly");
    }
  }
  return shape;
}

void Loader::load_mesh_file(const Json& value, const JsonPath& path, Shape& shape) {
  shape.type = Shape::Type::mesh;
  std::string file = string(required(value, path, "file"), path.field("file"));
  std::string unit_text = string(required(value, path, "unit"), path.field("unit"));
  std::string error;
  std::optional<Unit> unit = parse_unit(unit_text, error);
  if (!unit) fail(path.field("unit"), "cannot read " + short_dump(value["unit"]) + ": " + error);
  if (!(unit->dimension == runtime_dim::length))
    fail(path.field("unit"), "expected length (e.g. m), got " + short_dump(value["unit"]) + " (" +
                                 dimension_name(unit->dimension) + ")");

  std::filesystem::path full = base_directory_ / file;
  Real scale = static_cast<Real>(unit->to_reference);
  std::string extension = full.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".ply") {
    load_ply_file(full, file, scale, path, shape);
    return;
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = full.parent_path().string();
  tinyobj::ObjReader reader;
  if (!std::filesystem::is_regular_file(full) || !reader.ParseFromFile(full.string(), config)) {
    std::string reason = reader.Error();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
    fail(path.field("file"), "cannot read mesh '" + file + "'" + (reason.empty() ? "" : ": " + reason));
  }
  const auto& vertices = reader.GetAttrib().vertices;
  for (size_t i = 0; i + 2 < vertices.size(); i += 3) {
    sg::vec3_rep p{vertices[i] * scale, vertices[i + 1] * scale, vertices[i + 2] * scale};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(path.field("file"), "mesh '" + file + "' has a non-finite vertex");
    shape.positions.push_back(sg::from_raw<PointObject>(p));
  }
  // Texture coordinates have their own indices in OBJ: with them, each distinct
  // (position, texcoord) pair becomes one vertex.
  const auto& texcoords = reader.GetAttrib().texcoords;
  bool textured = !texcoords.empty();
  for (const tinyobj::shape_t& obj_shape : reader.GetShapes())
    for (const tinyobj::index_t& index : obj_shape.mesh.indices)
      textured = textured && index.texcoord_index >= 0 && 2 * static_cast<size_t>(index.texcoord_index) + 1 < texcoords.size();
  std::vector<PointObject> obj_positions;
  if (textured) obj_positions.swap(shape.positions);
  std::map<std::pair<int, int>, uint32_t> vertex_of;
  for (const tinyobj::shape_t& obj_shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : obj_shape.mesh.indices) {
      size_t count = textured ? obj_positions.size() : shape.positions.size();
      if (index.vertex_index < 0 || static_cast<size_t>(index.vertex_index) >= count)
        fail(path.field("file"), "mesh '" + file + "' has a face with a vertex index out of range");
      if (!textured) {
        shape.indices.push_back(static_cast<uint32_t>(index.vertex_index));
        continue;
      }
      auto [found, inserted] = vertex_of.try_emplace({index.vertex_index, index.texcoord_index},
                                                     static_cast<uint32_t>(shape.positions.size()));
      if (inserted) {
        shape.positions.push_back(obj_positions[index.vertex_index]);
        shape.uvs.push_back({texcoords[2 * index.texcoord_index], texcoords[2 * index.texcoord_index + 1]});
      }
      shape.indices.push_back(found->second);
    }
  }
  if (shape.indices.empty() || shape.indices.size() % 3 != 0)
    fail(path.field("file"), "mesh '" + file + "' has no triangles");
}

// PLY: positions and faces; vertex normals are read but not used (the renderer
// shades with geometric normals).
void Loader::load_ply_file(const std::filesystem::path& full, const std::string& file, Real scale,
                           const JsonPath& path, Shape& shape) {
  std::ifstream in(full, std::ios::binary);
  if (!std::filesystem::is_regular_file(full) || !in) fail(path.field("file"), "cannot read mesh '" + file + "'");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  PlyMesh mesh;
  try {
    mesh = parse_ply(bytes);
  } catch (const PlyError& error) {
    fail(path.field("file"), "cannot read mesh '" + file + "': " + error.what());
  }
  for (const std::array<float, 3>& p : mesh.positions) {
    sg::vec3_rep scaled{p[0] * scale, p[1] * scale, p[2] * scale};
    if (!std::isfinite(scaled.x) || !std::isfinite(scaled.y) || !std::isfinite(scaled.z))
      fail(path.field("file"), "mesh '" + file + "' has a non-finite vertex");
    shape.positions.push_back(sg::from_raw<PointObject>(scaled));
  }
  for (const std::array<float, 2>& uv : mesh.uvs) {
    if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) fail(path.field("file"), "mesh '" + file + "' has a non-finite texture coordinate");
    shape.uvs.push_back({uv[0], uv[1]});
  }
  shape.indices = std::move(mesh.indices);
  if (shape.indices.empty()) fail(path.field("file"), "mesh '" + file + "' has no triangles");
}

void Loader::load_triangles(const Json& value, const JsonPath& path, Shape& shape) {
  shape.type = Shape::Type::mesh;
  const Json& positions = required(value, path, "positions");
  JsonPath positions_path = path.field("positions");
  object(positions, positions_path, {"value", "unit"});
  const Json& points = required(positions, positions_path, "value");
  Unit unit = parse_unit_field(positions, positions_path);
  if (!(unit.dimension == runtime_dim::length))
    fail(positions_path, "expected length (e.g. m), got " + short_dump(positions) + " (" +
                             dimension_name(unit.dimension) + ")");
  if (!points.is_array()) fail(positions_path.field("value"), "expected an array of [x, y, z]");
  for (size_t i = 0; i < points.size(); ++i) {
    JsonPath point_path = positions_path.field("value").index(i);
    if (!points[i].is_array() || points[i].size() != 3) fail(point_path, "expected [x, y, z], got " + short_dump(points[i]));
    sg::vec3_rep p;
    for (int axis = 0; axis < 3; ++axis) {
      if (!points[i][axis].is_number()) fail(point_path.index(axis), "expected a number");
      double coordinate = points[i][axis].get<double>() * unit.to_reference;
      require_float_range(point_path.index(axis), coordinate);
      p[axis] = static_cast<Real>(coordinate);
    }
    shape.positions.push_back(sg::from_raw<PointObject>(p));
  }
  const Json& indices = required(value, path, "indices");
  if (!indices.is_array() || indices.empty() || indices.size() % 3 != 0)
    fail(path.field("indices"), "expected a non-empty array of vertex indices, three per triangle");
  int last = static_cast<int>(shape.positions.size()) - 1;
  if (last < 0) fail(positions_path.field("value"), "expected at least 3 points");
  for (size_t i = 0; i < indices.size(); ++i)
    shape.indices.push_back(static_cast<uint32_t>(integer(indices[i], path.field("indices").index(i), 0, last)));
  if (value.contains("uvs")) {
    const Json& uvs = value["uvs"];
    JsonPath uvs_path = path.field("uvs");
    if (!uvs.is_array() || uvs.size() != shape.positions.size())
      fail(uvs_path, "expected one [u, v] per position (" + std::to_string(shape.positions.size()) + ")");
    for (size_t i = 0; i < uvs.size(); ++i) {
      if (!uvs[i].is_array() || uvs[i].size() != 2) fail(uvs_path.index(i), "expected [u, v], got " + short_dump(uvs[i]));
      shape.uvs.push_back({number(uvs[i][0], uvs_path.index(i).index(0), -1e6, 1e6),
                           number(uvs[i][1], uvs_path.index(i).index(1), -1e6, 1e6)});
    }
  }
}

ObjectToWorld Loader::load_transform(const Json& value, const JsonPath& path) {
  if (!value.is_array()) fail(path, "expected an array of transform steps, got " + short_dump(value));
  // The steps compose into one map<object, world>; the spaces between steps are anonymous.
  sg::mat4_rep result(1.0f);
  for (size_t i = 0; i < value.size(); ++i) {
    JsonPath step_path = path.index(i);
    const Json& step = value[i];
    if (!step.is_object() || step.size() != 1)
      fail(step_path, "expected one of {\"translate\": ...}, {\"rotate\": ...}, {\"scale\": ...}");
    sg::mat4_rep m(1.0f);
    if (step.contains("translate")) {
      Triple t = triple(step["translate"], step_path.field("translate"), runtime_dim::length);
      for (int r = 0; r < 3; ++r) m[3][r] = static_cast<Real>(t[r]);
    } else if (step.contains("rotate")) {
      JsonPath rotate_path = step_path.field("rotate");
      const Json& rotate = object(step["rotate"], rotate_path, {"axis", "angle"});
      Triple axis = triple(required(rotate, rotate_path, "axis"), rotate_path.field("axis"), runtime_dim::none);
      double angle = scalar(required(rotate, rotate_path, "angle"), rotate_path.field("angle"), runtime_dim::angle);
      double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      if (!(norm > 0)) fail(rotate_path.field("axis"), "must not be zero");
      double x = axis[0] / norm, y = axis[1] / norm, z = axis[2] / norm;
      double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
      double r[3][3] = {{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
                        {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
                        {t * x * z - s * y, t * y * z + s * x, t * z * z + c}};
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) m[col][row] = static_cast<Real>(r[row][col]);
    } else if (step.contains("scale")) {
      const Json& scale = step["scale"];
      Triple s = scale.is_array() ? triple(scale, step_path.field("scale"), runtime_dim::none)
                                  : Triple{0, 0, 0};
      if (!scale.is_array()) s.fill(scalar(scale, step_path.field("scale"), runtime_dim::none));
      for (int r = 0; r < 3; ++r) {
        if (!(std::fabs(s[r]) > 0)) fail(step_path.field("scale"), "must not be zero");
        m[r][r] = static_cast<Real>(s[r]);
      }
    } else {
      fail(step_path, "expected one of {\"translate\": ...}, {\"rotate\": ...}, {\"scale\": ...}");
    }
    result = m * result;  // later steps apply after earlier ones
  }
  // Each step is non-singular, but float products can still underflow or
  // overflow (two 1e-30 scales): the inverse must exist in float.
  sg::mat4_rep inverse = glm::inverse(result);
  Real determinant = glm::determinant(sg::mat3_rep(result));
  bool finite = std::isnormal(determinant);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(result[c][r]) && std::isfinite(inverse[c][r]);
  if (!finite)
    fail(path, std::string("is singular in ") + kRealName + " precision (its scales multiply to 0 or infinity)");
  return ObjectToWorld::from_matrix(result);
}

void Loader::load_light(const Json& value, const JsonPath& path, Scene& scene) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  if (type != "point" && type != "spot")
    fail(path.field("type"), "expected \"point\", \"spot\" or \"environment\", got " + short_dump(value["type"]));
  if (type == "point")
    object(value, path, {"type", "name", "position", "intensity", "power"});
  else
    object(value, path, {"type", "name", "position", "look_at", "intensity", "power", "cone_angle", "cone_delta"});
  PointWorld position = typed_point<PointWorld>(required(value, path, "position"), path.field("position"));
  if (value.contains("intensity") == value.contains("power"))
    fail(path, "expected exactly one of 'intensity' and 'power'");
  // The solid angle the light's power spreads over: the sphere, or the spot's
  // cone with its falloff band counted at half (pbrt-v3's SpotLight::Power).
  SpotLight spot;
  quantity<dim::solid_angle> spread = Real(4) * sg::pi * units::steradian;
  if (type == "spot") {
    spot.position = position;
    PointWorld look_at = typed_point<PointWorld>(required(value, path, "look_at"), path.field("look_at"));
    if (!(sg::length(look_at - position) > sg::zero)) fail(path.field("look_at"), "must differ from position");
    spot.direction = sg::normalize(look_at - position);
    spot.cone_angle = typed_scalar<dim::angle>(required(value, path, "cone_angle"), path.field("cone_angle"));
    if (!(spot.cone_angle > sg::zero && spot.cone_angle <= Real(180) * units::degree))
      fail(path.field("cone_angle"), "expected an angle in (0 deg, 180 deg]");
    if (value.contains("cone_delta")) {
      spot.cone_delta = typed_scalar<dim::angle>(value["cone_delta"], path.field("cone_delta"));
      if (!(spot.cone_delta >= sg::zero && spot.cone_delta <= spot.cone_angle))
        fail(path.field("cone_delta"), "expected an angle in [0 deg, cone_angle]");
    }
    Real cos_total = sg::cos(spot.cone_angle), cos_start = sg::cos(spot.cone_angle - spot.cone_delta);
    spread = (2 * sg::pi * (1 - Real(0.5) * (cos_start + cos_total))) * units::steradian;
  }
  Intensity intensity;
  if (value.contains("intensity")) {
    intensity = typed_spectrum<dim::intensity>(value["intensity"], path.field("intensity"));
  } else {
    sg::spectrum<dim::power> power = typed_spectrum<dim::power>(value["power"], path.field("power"));
    intensity = power / spread;
  }
  if (intensity.r() < sg::zero || intensity.g() < sg::zero || intensity.b() < sg::zero)
    fail(path, "light output must not be negative");
  if (type == "point") {
    scene.point_lights.push_back({position, intensity});
  } else {
    spot.intensity = intensity;
    scene.spot_lights.push_back(spot);
  }
}

EnvironmentLight Loader::load_environment(const Json& value, const JsonPath& path) {
  object(value, path, {"type", "name", "radiance", "file", "transform"});
  EnvironmentLight light;
  light.radiance = value.contains("radiance") ? typed_spectrum<dim::radiance>(value["radiance"], path.field("radiance"))
                                              : Radiance(Real(1) * units::radiance_unit);
  if (!value.contains("radiance") && !value.contains("file"))
    fail(path, "expected 'radiance', 'file' or both");
  if (light.radiance.r() < sg::zero || light.radiance.g() < sg::zero || light.radiance.b() < sg::zero)
    fail(path.field("radiance"), "radiance must not be negative");
  if (value.contains("file")) {
    Image image = read_image_file(value["file"], path.field("file"), light.file);
    light.map = std::make_shared<MipMap>(std::move(image), TextureWrap::longitude_latitude);
  }
  if (value.contains("transform")) {
    const Json& steps = value["transform"];
    if (steps.is_array())
      for (size_t i = 0; i < steps.size(); ++i)
        if (!steps[i].is_object() || !steps[i].contains("rotate"))
          fail(path.field("transform").index(i), "an environment light can only be rotated");
    light.render_from_light = sg::from_raw<LightToWorld>(sg::raw(load_transform(steps, path.field("transform"))));
  }
  return light;
}

std::string line_and_column(std::string_view text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// nlohmann's messages start with "[json.exception.<kind>.<id>] ".
std::string without_exception_id(const std::string& message) {
  size_t close = message.find("] ");
  return message.rfind("[json.exception.", 0) == 0 && close != std::string::npos ? message.substr(close + 2) : message;
}

}  // namespace

Image read_checked_image(const std::filesystem::path& file, const ImageFileReader& reader) {
  Image image;
  if (reader) {
    image = reader(file);
  } else {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension != ".pfm") throw std::runtime_error("this program reads PFM images only (no OpenImageIO)");
    image = read_pfm(file);
  }
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != 3 * static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
    throw std::runtime_error("it has no pixels");
  for (float v : image.rgb)
    if (!std::isfinite(v) || v < 0) throw std::runtime_error("it has a negative or non-finite value");
  return image;
}

Scene parse_scene(std::string_view json_text, std::string_view display_name,
                  const std::filesystem::path& base_directory, const SceneLoadOptions& options) {
  Json root;
  try {
    root = Json::parse(json_text.begin(), json_text.end());
  } catch (const Json::parse_error& error) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> our own line:col.
    std::string message = error.what();
    size_t colon = message.find(": ", message.find("parse error"));
    std::string reason = printable(colon == std::string::npos ? message : message.substr(colon + 2));
    size_t at = error.byte == 0 ? 0 : error.byte - 1;
    throw SceneError(std::string(display_name) + ":" + line_and_column(json_text, at) + ": invalid JSON: " + reason);
  } catch (const Json::exception& error) {  // e.g. a number too large for a double
    throw SceneError(std::string(display_name) + ": invalid JSON: " + printable(without_exception_id(error.what())));
  }
  try {
    return Loader(display_name, base_directory, options).load(root);
  } catch (const Json::exception& error) {  // a value of a type the loader did not expect
    throw SceneError(std::string(display_name) + ": " + printable(without_exception_id(error.what())));
  }
}

Scene load_scene(const std::filesystem::path& file, const SceneLoadOptions& options) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream || std::filesystem::is_directory(file)) throw SceneError(file.string() + ": cannot open scene file");
  std::ostringstream text;
  text << stream.rdbuf();
  return parse_scene(text.str(), file.string(), file.parent_path(), options);
}

}  // namespace safegi::render
