#include "safegi/cpu_renderer/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "scene/json_loader.hpp"
#include "util/printable.hpp"

namespace safegi::render {

namespace json {

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
    for (const auto& [name, value] : materials.items())
      if (scene.materials[material_index[name]].mix)
        resolve_mix(scene, material_index[name], value, top.field("materials").field(name), material_index);
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
         {"resolution", "spp", "integrator", "max_depth", "mis", "light_samples", "light_strategy", "filter",
          "russian_roulette", "russian_roulette_depth", "photons", "photon_radius", "sppm_iterations",
          "sppm_photons_per_iteration", "sppm_radius"});
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
    else if (name == "bdpt") settings.integrator = IntegratorType::bdpt;
    else if (name == "sppm") settings.integrator = IntegratorType::sppm;
    else fail(path.field("integrator"), "expected \"direct\", \"path\", \"photon\", \"bdpt\" or \"sppm\", got " + short_dump(value["integrator"]));
  }
  if (value.contains("mis")) settings.mis = boolean(value["mis"], path.field("mis"));
  if (value.contains("light_samples"))
    settings.light_samples = integer(value["light_samples"], path.field("light_samples"), 1, 1024);
  if (value.contains("light_strategy")) {
    std::string name = string(value["light_strategy"], path.field("light_strategy"));
    std::optional<LightStrategy> strategy = light_strategy_named(name);
    if (!strategy)
      fail(path.field("light_strategy"),
           "expected " + quoted_choices(kLightStrategyNames) + ", got " + short_dump(value["light_strategy"]));
    settings.light_strategy = *strategy;
  }
  if (value.contains("filter")) settings.filter = pixel_filter(value["filter"], path.field("filter"));
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
  if (value.contains("sppm_iterations"))
    settings.sppm_iterations = integer(value["sppm_iterations"], path.field("sppm_iterations"), 1, 1 << 24);
  if (value.contains("sppm_photons_per_iteration"))
    settings.sppm_photons_per_iteration =
        integer(value["sppm_photons_per_iteration"], path.field("sppm_photons_per_iteration"), 1, 1 << 28);
  if (value.contains("sppm_radius")) {
    settings.sppm_radius = typed_scalar<dim::length>(value["sppm_radius"], path.field("sppm_radius"));
    if (!(settings.sppm_radius > sg::zero)) fail(path.field("sppm_radius"), "must be positive");
  }
}

// {"type": "gaussian", "radius": [2, 2], "alpha": 2, "mode": "splat"}; mitchell's "b" and "c", sinc's "tau".
PixelFilter Loader::pixel_filter(const Json& value, const JsonPath& path) {
  object(value, path, {"type", "radius", "alpha", "b", "c", "tau", "mode"});
  const std::string name = string(required(value, path, "type"), path.field("type"));
  const std::optional<PixelFilterType> type = pixel_filter_named(name);
  if (!type)
    fail(path.field("type"),
         "expected " + quoted_choices(kPixelFilterNames) + ", got " + short_dump(value["type"]));
  PixelFilter filter;
  filter.type = *type;
  if (value.contains("radius")) {
    const Json& radius = value["radius"];
    if (!radius.is_array() || radius.size() != 2)
      fail(path.field("radius"), "expected [x, y] in pixels, got " + short_dump(radius));
    filter.radius_x = number(radius[0], path.field("radius").index(0), kMinFilterRadius, kMaxFilterRadius);
    filter.radius_y = number(radius[1], path.field("radius").index(1), kMinFilterRadius, kMaxFilterRadius);
  } else {
    filter.radius_x = filter.radius_y = default_filter_radius(filter.type);
  }
  if (value.contains("alpha")) filter.gaussian_alpha = number(value["alpha"], path.field("alpha"), 1e-6, 1e6);
  if (value.contains("b")) filter.mitchell_b = number(value["b"], path.field("b"), -10, 10);
  if (value.contains("c")) filter.mitchell_c = number(value["c"], path.field("c"), -10, 10);
  if (value.contains("tau")) filter.sinc_tau = number(value["tau"], path.field("tau"), 1e-3, 1e3);
  if (value.contains("mode")) {
    const std::optional<PixelFilterMode> mode = pixel_filter_mode_named(string(value["mode"], path.field("mode")));
    if (!mode)
      fail(path.field("mode"), "expected " + quoted_choices(kPixelFilterModeNames) + ", got " + short_dump(value["mode"]));
    filter.mode = *mode;
  }
  return filter;
}

CameraProjection Loader::projection(const Json& value, const JsonPath& path) {
  if (!value.contains("projection")) return CameraProjection::perspective;
  const std::string name = string(value["projection"], path.field("projection"));
  if (name == "perspective") return CameraProjection::perspective;
  if (name == "orthographic") return CameraProjection::orthographic;
  if (name == "environment") return CameraProjection::environment;
  fail(path.field("projection"),
       "expected \"perspective\", \"orthographic\" or \"environment\", got " + short_dump(value["projection"]));
}

void Loader::load_camera(const Json& value, const JsonPath& path, Camera& camera) {
  object(value, path, {"projection", "position", "look_at", "up", "fov", "view_size", "lens_radius", "focus_distance", "shutter"});
  camera.projection = projection(value, path);
  camera.position = typed_point<PointWorld>(required(value, path, "position"), path.field("position"));
  camera.look_at = typed_point<PointWorld>(required(value, path, "look_at"), path.field("look_at"));
  Triple up = triple(required(value, path, "up"), path.field("up"), runtime_dim::none);
  if (camera.projection == CameraProjection::perspective) {
    Angle fov = typed_scalar<dim::angle>(required(value, path, "fov"), path.field("fov"));
    if (!(fov > Real(0) * units::degree && fov < Real(180) * units::degree))
      fail(path.field("fov"), "expected an angle in (0 deg, 180 deg)");
    camera.fov = fov;
  } else if (value.contains("fov")) {
    fail(path.field("fov"), "only a perspective camera has a field of view");
  }
  if (camera.projection == CameraProjection::orthographic) {
    camera.view_size = typed_scalar<dim::length>(required(value, path, "view_size"), path.field("view_size"));
    if (!(camera.view_size > sg::zero && sg::raw(camera.view_size) < std::numeric_limits<Real>::infinity()))
      fail(path.field("view_size"), "must be positive");
  } else if (value.contains("view_size")) {
    fail(path.field("view_size"), "only an orthographic camera has a view size");
  }
  if (camera.projection == CameraProjection::environment && value.contains("lens_radius"))
    fail(path.field("lens_radius"), "an environment camera has no lens");
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

RenderFromObject Loader::load_transform(const Json& value, const JsonPath& path) {
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
  return RenderFromObject::from_matrix(result);
}

void Loader::load_light(const Json& value, const JsonPath& path, Scene& scene) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  if (type != "point" && type != "spot")
    fail(path.field("type"), "expected \"point\", \"spot\" or \"environment\", got " + short_dump(value["type"]));
  if (type == "point")
    object(value, path, {"type", "name", "position", "intensity", "power", "map"});
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
    std::optional<IntensityMap> profile;
    if (value.contains("map")) {
      profile = load_intensity_map(value["map"], path.field("map"));
      // "power" is the light's whole output, per channel: the map shares it out.
      if (value.contains("power")) {
        const sg::vec3_rep mean = sg::raw(mean_intensity_factor(*profile)), spread_out = sg::raw(intensity);
        for (int c = 0; c < 3; ++c)
          if (spread_out[c] > 0 && !(mean[c] > 0))
            fail(path.field("map"), "the map sends no light in a colour channel that 'power' has");
        intensity = sg::from_raw<Intensity>(sg::vec3_rep(mean.x > 0 ? spread_out.x / mean.x : 0,
                                                         mean.y > 0 ? spread_out.y / mean.y : 0,
                                                         mean.z > 0 ? spread_out.z / mean.z : 0));
      }
    }
    scene.point_lights.push_back({position, intensity, std::move(profile)});
  } else {
    spot.intensity = intensity;
    scene.spot_lights.push_back(spot);
  }
}

IntensityMap Loader::load_intensity_map(const Json& value, const JsonPath& path) {
  object(value, path, {"layout", "file", "fov", "transform"});
  IntensityMap profile;
  const std::string layout = string(required(value, path, "layout"), path.field("layout"));
  if (layout == "projection") {
    profile.layout = IntensityMap::Layout::projection;
    profile.fov = typed_scalar<dim::angle>(required(value, path, "fov"), path.field("fov"));
    if (!(profile.fov > sg::zero && profile.fov < Real(180) * units::degree))
      fail(path.field("fov"), "expected an angle in (0 deg, 180 deg)");
  } else if (layout == "goniometric") {
    if (value.contains("fov")) fail(path.field("fov"), "only a projection map has a field of view");
  } else {
    fail(path.field("layout"), "expected \"goniometric\" or \"projection\", got " + short_dump(value["layout"]));
  }
  if (value.contains("file")) {
    Image image = read_image_file(value["file"], path.field("file"), profile.file);
    const bool projection = profile.layout == IntensityMap::Layout::projection;
    profile.map = std::make_shared<MipMap>(std::move(image), projection ? TextureWrap::clamp : TextureWrap::longitude_latitude);
  }
  profile.render_from_light = load_rotation(value, path, "a light's map");
  return profile;
}

// An optional "transform" of rotations only: the frame of `what`.
RenderFromLight Loader::load_rotation(const Json& value, const JsonPath& path, const std::string& what) {
  if (!value.contains("transform")) return RenderFromLight{};
  const Json& steps = value["transform"];
  if (steps.is_array())
    for (size_t i = 0; i < steps.size(); ++i)
      if (!steps[i].is_object() || !steps[i].contains("rotate"))
        fail(path.field("transform").index(i), what + " can only be rotated");
  return sg::from_raw<RenderFromLight>(sg::raw(load_transform(steps, path.field("transform"))));
}

EnvironmentLight Loader::load_environment(const Json& value, const JsonPath& path) {
  object(value, path, {"type", "name", "radiance", "file", "transform", "light_samples"});
  EnvironmentLight light;
  if (value.contains("light_samples"))
    light.samples = integer(value["light_samples"], path.field("light_samples"), 1, kMaxEmitterSamples);
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
  light.render_from_light = load_rotation(value, path, "an environment light");
  return light;
}

}  // namespace json

namespace {

using json::Json;

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
    return json::Loader(display_name, base_directory, options).load(root);
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
