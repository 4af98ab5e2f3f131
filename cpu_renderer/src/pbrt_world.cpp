// The importer's world block: attributes, materials, textures, lights, shapes
// and object instances (pbrt-v3's core/api.cpp, mapped onto our Scene).
#include <array>
#include <cmath>

#include "pbrt_importer.hpp"
#include "ply.hpp"

namespace safegi::render::pbrt {

namespace {

template <class M>
M& writable(std::shared_ptr<M>& shared) {
  if (shared.use_count() > 1) shared = std::make_shared<M>(*shared);
  return *shared;
}

// The parameters each supported material reads: a shape that carries one of
// them gets its own copy of the material (pbrt-v3's GetMaterialForShape).
struct MaterialParams {
  std::string_view type;
  std::array<std::string_view, 3> names;  // empty names pad the list
};
constexpr MaterialParams kMaterialParams[] = {
    {"matte", {"Kd", "sigma", "bumpmap"}},
    {"mirror", {"Kr", "bumpmap", ""}},
};
constexpr std::string_view kLaterMaterials[] = {"plastic", "glass", "uber"};

bool reads_material_params(const std::string& type, const ParamSet& shape) {
  for (const MaterialParams& m : kMaterialParams)
    if (m.type == type)
      for (std::string_view name : m.names)
        if (!name.empty() && shape.contains(name)) return true;
  return false;
}

double determinant3(const Matrix& m) { return glm::determinant(glm::dmat3(m)); }

// Column lengths of the linear part equal and columns orthogonal: angles survive.
bool is_similarity(const Matrix& m, double tolerance) {
  glm::dmat3 l(m);
  double s = glm::length(l[0]);
  return s > 0 && std::fabs(glm::length(l[1]) - s) <= tolerance * s && std::fabs(glm::length(l[2]) - s) <= tolerance * s &&
         std::fabs(glm::dot(l[0], l[1])) <= tolerance * s * s && std::fabs(glm::dot(l[0], l[2])) <= tolerance * s * s &&
         std::fabs(glm::dot(l[1], l[2])) <= tolerance * s * s;
}

}  // namespace

void Importer::world_directive(const Directive& d) {
  const std::string& name = d.name;
  if (name == "AttributeBegin" || name == "ObjectBegin") {
    if (name == "ObjectBegin") {
      if (current_object_) fail(d.range, "ObjectBegin inside the definition of object \"" + current_object_name_ + "\"");
      current_object_name_ = d.strings[0];
      current_object_ = &objects_[d.strings[0]];
      current_object_->clear();
    }
    attribute_stack_.push_back(state_);
    transform_stack_.push_back(state_.ctm);
  } else if (name == "AttributeEnd" || name == "ObjectEnd") {
    if (name == "ObjectEnd") {
      if (!current_object_) fail(d.range, "ObjectEnd without ObjectBegin");
      current_object_ = nullptr;
    }
    if (attribute_stack_.empty() || transform_stack_.empty())
      fail(d.range, name + " without a matching " + (name == "ObjectEnd" ? "ObjectBegin" : "AttributeBegin"));
    state_ = std::move(attribute_stack_.back());
    attribute_stack_.pop_back();
    state_.ctm = transform_stack_.back();
    transform_stack_.pop_back();
  } else if (name == "TransformBegin") {
    transform_stack_.push_back(state_.ctm);
  } else if (name == "TransformEnd") {
    if (transform_stack_.empty()) fail(d.range, "TransformEnd without a matching TransformBegin");
    state_.ctm = transform_stack_.back();
    transform_stack_.pop_back();
  } else if (name == "ReverseOrientation") {
    state_.reverse_orientation = !state_.reverse_orientation;
  } else if (name == "Material" || name == "MakeNamedMaterial") {
    material(d, name == "MakeNamedMaterial");
  } else if (name == "NamedMaterial") {
    auto found = state_.named_materials->find(d.strings[0]);
    if (found == state_.named_materials->end())
      fail(d.string_ranges[0], "no material named \"" + d.strings[0] + "\"", "MakeNamedMaterial defines one");
    state_.material = found->second;
  } else if (name == "Texture") {
    texture(d);
  } else if (name == "LightSource") {
    light_source(d);
  } else if (name == "AreaLightSource") {
    area_light_source(d);
  } else if (name == "Shape") {
    shape(d);
  } else if (name == "ObjectInstance") {
    object_instance(d);
  } else if (name == "WorldEnd") {
    if (current_object_) fail(d.range, "WorldEnd inside the definition of object \"" + current_object_name_ + "\"");
    if (!attribute_stack_.empty()) warn(d.range, "WorldEnd with an AttributeBegin still open");
    block_ = Block::ended;
  } else if (name == "WorldBegin") {
    fail(d.range, "a second WorldBegin", "a scene file renders one image: one WorldBegin ... WorldEnd block");
  } else {
    fail(d.range, name + " is not supported inside the world block");
  }
}

// ---------------------------------------------------------------------------
// Materials and textures

Reflectance Importer::reflectance(ParamSet& params, const char* name, double fallback) {
  Rgb rgb{fallback, fallback, fallback};
  if (std::optional<SpectrumValue> value = params.spectrum(name, true)) {
    rgb = value->rgb;
    if (!value->texture.empty()) {
      auto found = state_.spectrum_textures->find(value->texture);
      if (found == state_.spectrum_textures->end())
        fail(value->param->values, "no spectrum texture named \"" + value->texture + "\"",
             "Texture \"" + value->texture + "\" \"spectrum\" ... defines one");
      rgb = found->second.value;
    }
    for (double c : rgb)
      if (!(c >= 0 && c <= 1))
        params.fail_at(*value->param, "\"" + std::string(name) + "\" of " + params.context() +
                                          " must lie in [0, 1] in every channel",
                       "above 1 a surface reflects more light than it receives");
  }
  return sg::from_raw<Reflectance>(sg::vec3_rep(static_cast<Real>(rgb[0]), static_cast<Real>(rgb[1]),
                                             static_cast<Real>(rgb[2])));
}

Material Importer::convert_material(const std::string& type, ParamSet& params) {
  Material material;
  material.name = type;
  if (type == "matte") {
    params.reject("sigma", "Oren-Nayar roughness (only sigma 0, Lambert)", 0.0);
    params.reject("bumpmap", "bump mapping");
    material.type = Material::Type::lambert;
    material.diffuse = reflectance(params, "Kd", 0.5);
    if (sg::is_black(material.diffuse)) material.type = Material::Type::black;
  } else if (type == "mirror") {
    params.reject("bumpmap", "bump mapping");
    material.type = Material::Type::mirror;
    material.specular = reflectance(params, "Kr", 0.9);
    if (sg::is_black(material.specular)) material.type = Material::Type::black;
  }
  return material;
}

void Importer::material(const Directive& d, bool named) {
  auto instance = std::make_shared<MaterialInstance>();
  instance->params = d.params;
  ParamSet params(instance->params, named ? "MakeNamedMaterial \"" + d.strings[0] + "\"" : "Material \"" + d.strings[0] + "\"");
  if (named) {
    const Param* type = params.find("type", {ParamType::string});
    if (!type || type->strings.size() != 1)
      fail(d.string_ranges[0], "MakeNamedMaterial \"" + d.strings[0] + "\" needs \"string type\", e.g. \"matte\"");
    instance->type = type->strings[0];
    instance->at = type->values;
  } else {
    instance->type = d.strings[0];
    instance->at = d.string_ranges[0];
  }
  const std::string& type = instance->type;
  bool supported = false;
  for (const MaterialParams& m : kMaterialParams) supported = supported || m.type == type;
  if (!supported) {
    for (std::string_view later : kLaterMaterials)
      if (type == later) fail(instance->at, "material \"" + type + "\" is not supported yet", "supported: \"matte\", \"mirror\"");
    if (type.empty() || type == "none")
      fail(instance->at, "an invisible interface material (\"" + type + "\") is not supported",
           "it only bounds participating media, which are not supported either");
    fail(instance->at, "material \"" + type + "\" is not supported", "supported: \"matte\", \"mirror\"");
  }
  Material converted = convert_material(type, params);
  report_unused(params);
  if (converted.type == Material::Type::black) {
    instance->index = -1;  // absorbs everything, as pbrt-v3's black matte does
  } else {
    instance->index = static_cast<int>(result_.scene.materials.size());
    result_.scene.materials.push_back(converted);
  }
  if (named)
    writable(state_.named_materials)[d.strings[0]] = instance;
  else
    state_.material = instance;
}

int Importer::material_index(const MaterialInstance& material, ParamSet& shape_params) {
  if (material.index != -2 && !reads_material_params(material.type, shape_params)) return material.index;
  // The shape's own values win over the material's.
  ParamSet material_params(material.params, "the shape's material \"" + material.type + "\"");
  shape_params.set_fallback(&material_params);
  Material converted = convert_material(material.type, shape_params);
  shape_params.set_fallback(nullptr);
  if (converted.type == Material::Type::black) return -1;
  result_.scene.materials.push_back(converted);
  return static_cast<int>(result_.scene.materials.size()) - 1;
}

void Importer::texture(const Directive& d) {
  const std::string &name = d.strings[0], &type = d.strings[1], &texture_class = d.strings[2];
  bool spectrum = type == "spectrum" || type == "color";
  if (!spectrum && type != "float")
    fail(d.string_ranges[1], "texture type \"" + type + "\" is unknown", "pbrt-v3 has \"spectrum\" (or \"color\") and \"float\"");
  ParamSet params(d.params, "Texture \"" + name + "\"");
  TextureEntry entry;
  entry.texture_class = texture_class;
  entry.at = d.string_ranges[2];
  if (texture_class == "constant") {
    if (spectrum) {
      std::optional<SpectrumValue> value = params.spectrum("value", false);
      entry.value = value ? value->rgb : Rgb{1, 1, 1};
    } else {
      double value = params.one_float("value", 1);
      entry.value = {value, value, value};
    }
  } else if (texture_class == "imagemap" || texture_class == "checkerboard") {
    fail(entry.at, "texture \"" + texture_class + "\" is not supported yet", "supported: \"constant\"");
  } else {
    fail(entry.at, "texture \"" + texture_class + "\" is not supported", "supported: \"constant\"");
  }
  report_unused(params);
  writable(spectrum ? state_.spectrum_textures : state_.float_textures)[name] = entry;
}

// ---------------------------------------------------------------------------
// Lights

void Importer::light_source(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "LightSource \"" + type + "\"");
  if (type == "point" || type == "spot") {
    auto read = [&](const char* name) {
      std::optional<SpectrumValue> value = params.spectrum(name, false);
      Rgb rgb = value ? value->rgb : Rgb{1, 1, 1};
      for (double c : rgb)
        if (c < 0) params.fail_at(*value->param, "light output must not be negative");
      return rgb;
    };
    Rgb i = read("I"), s = read("scale");
    // Intensity in the unit system that keeps pbrt's pixel values (pbrt_import.hpp).
    double unit2 = options_.metres_per_unit * options_.metres_per_unit;
    sg::vec3_rep rgb(static_cast<Real>(i[0] * s[0] * unit2), static_cast<Real>(i[1] * s[1] * unit2),
                  static_cast<Real>(i[2] * s[2] * unit2));
    Intensity intensity = sg::from_raw<Intensity>(rgb);
    Triple from = params.one_point("from").value_or(Triple{0, 0, 0});
    glm::dvec3 from_v(from[0], from[1], from[2]);
    if (type == "point") {
      // pbrt-v3 offsets "from" in world space: Translate(from) * CTM.
      glm::dvec3 at = glm::dvec3(state_.ctm * glm::dvec4(0, 0, 0, 1)) + from_v;
      result_.scene.point_lights.push_back({to_world_point(world_from_pbrt_world_, at, d.range), intensity});
    } else {
      Triple to = params.one_point("to").value_or(Triple{0, 0, 1});
      glm::dvec3 axis = glm::dvec3(to[0], to[1], to[2]) - from_v;
      if (!(glm::length(axis) > 0)) fail(d.range, "the spot light's \"from\" and \"to\" coincide");
      if (!is_similarity(state_.ctm, 1e-6))
        fail(d.range, "a spot light under a transform that scales unevenly or shears is not supported",
             "it would make the cone elliptic");
      Matrix m = world_from_pbrt_world_ * state_.ctm;
      SpotLight spot;
      spot.position = to_world_point(m, from_v, d.range);
      glm::dvec3 direction = glm::normalize(glm::dmat3(m) * axis);
      spot.direction = sg::normalize(sg::from_raw<vector<World, dim::dimensionless>>(sg::vec3_rep(direction)));
      spot.intensity = intensity;
      double cone = params.one_float("coneangle", 30), delta = params.one_float("conedeltaangle", 5);
      if (!(cone > 0 && cone <= 180)) fail(d.range, "\"float coneangle\" must lie in (0, 180] degrees");
      if (!(delta >= 0 && delta <= cone))
        fail(d.range, "\"float conedeltaangle\" must lie in [0, coneangle]",
             "the falloff starts at coneangle - conedeltaangle");
      spot.cone_angle = static_cast<Real>(cone) * units::degree;
      spot.cone_delta = static_cast<Real>(delta) * units::degree;
      result_.scene.spot_lights.push_back(spot);
    }
  } else if (type == "infinite") {
    fail(d.string_ranges[0], "light \"infinite\" is not supported yet", "supported: \"point\", \"spot\"");
  } else {
    fail(d.string_ranges[0], "light \"" + type + "\" is not supported", "supported: \"point\", \"spot\"");
  }
  report_unused(params);
}

void Importer::area_light_source(const Directive& d) {
  if (d.strings[0] != "diffuse" && d.strings[0] != "area")
    fail(d.string_ranges[0], "area light \"" + d.strings[0] + "\" is not supported", "supported: \"diffuse\"");
  ParamSet params(d.params, "AreaLightSource \"" + d.strings[0] + "\"");
  AreaLight light;
  light.at = d.string_ranges[0];
  Rgb l{1, 1, 1}, s{1, 1, 1};
  if (std::optional<SpectrumValue> value = params.spectrum("L", false)) l = value->rgb;
  if (std::optional<SpectrumValue> value = params.spectrum("scale", false)) s = value->rgb;
  for (int c = 0; c < 3; ++c) {
    light.radiance[c] = l[c] * s[c];
    if (!(light.radiance[c] >= 0)) fail(d.range, "emitted radiance must not be negative");
  }
  light.two_sided = params.one_bool("twosided", false);
  // Shadow rays per light for pbrt's direct-lighting integrator: noise only.
  params.one_int("samples", 1, 1, 1 << 20);
  params.one_int("nsamples", 1, 1, 1 << 20);
  report_unused(params);
  state_.area_light = light;
}

// ---------------------------------------------------------------------------
// Shapes

void Importer::shape(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "Shape \"" + type + "\"");
  ShapeSource source;
  source.at = d.string_ranges[0];
  source.object_to_pbrt_world = state_.ctm;
  source.reverse_orientation = state_.reverse_orientation;
  auto reject_alpha = [&] {
    for (const char* name : {"alpha", "shadowalpha"}) {
      const Param* alpha = params.find(name, {ParamType::floating, ParamType::texture});
      if (alpha && !(alpha->type == ParamType::floating && alpha->numbers.size() == 1 && alpha->numbers[0] == 1))
        params.fail_at(*alpha, std::string("\"") + name + "\" masks are not supported");
    }
  };
  if (type == "trianglemesh") {
    source.kind = ShapeSource::Kind::mesh;
    const Param* p = params.find("P", {ParamType::point3});
    if (!p) fail(d.range, "Shape \"trianglemesh\" needs \"point P\" (its vertices)");
    if (p->numbers.size() % 3 != 0 || p->numbers.empty())
      fail(p->values, "\"point P\" takes x y z per vertex: " + std::to_string(p->numbers.size()) + " numbers");
    for (size_t i = 0; i < p->numbers.size(); i += 3)
      source.positions.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
    const Param* indices = params.find("indices", {ParamType::integer});
    if (!indices && source.positions.size() == 3) {
      source.indices = {0, 1, 2};
    } else {
      if (!indices) fail(d.range, "Shape \"trianglemesh\" needs \"integer indices\" (three per triangle)");
      if (indices->numbers.empty() || indices->numbers.size() % 3 != 0)
        fail(indices->values, "\"integer indices\" takes three per triangle: " + std::to_string(indices->numbers.size()) +
                                  " values");
      for (double i : indices->numbers) {
        if (i != std::floor(i) || i < 0 || i >= static_cast<double>(source.positions.size()))
          fail(indices->values, "vertex index " + std::to_string(static_cast<long long>(std::floor(i))) +
                                    " is out of range: \"point P\" has " + std::to_string(source.positions.size()) +
                                    " vertices");
        source.indices.push_back(static_cast<uint32_t>(i));
      }
    }
    if (const Param* n = params.find("N", {ParamType::normal})) {
      if (n->numbers.size() != p->numbers.size())
        fail(n->values, "\"normal N\" needs one normal per vertex of \"point P\"");
      for (size_t i = 0; i < n->numbers.size(); i += 3)
        source.normals.emplace_back(n->numbers[i], n->numbers[i + 1], n->numbers[i + 2]);
    }
    // Texture coordinates, tangents and face ids: nothing here reads them.
    params.find("uv", {ParamType::floating, ParamType::point2});
    params.find("st", {ParamType::floating, ParamType::point2});
    params.find("S", {ParamType::vector3});
    params.find("faceIndices", {ParamType::integer});
    reject_alpha();
  } else if (type == "plymesh") {
    source.kind = ShapeSource::Kind::mesh;
    mesh_from_ply(d, params, source);
    params.reject("displacement", "displacement mapping");
    params.one_float("edgelength", 1);
    reject_alpha();
  } else if (type == "sphere") {
    source.kind = ShapeSource::Kind::sphere;
    source.radius = params.one_float("radius", 1);
    if (!(source.radius > 0)) fail(d.range, "a sphere's \"float radius\" must be positive");
    params.reject("zmin", "partial spheres", -source.radius);
    params.reject("zmax", "partial spheres", source.radius);
    params.reject("phimax", "partial spheres", 360.0);
  } else {
    fail(d.string_ranges[0], "shape \"" + type + "\" is not supported",
         "supported: \"trianglemesh\", \"plymesh\", \"sphere\"");
  }
  source.material = material_index(*state_.material, params);
  source.emission = state_.area_light;
  report_unused(params);
  if (current_object_) {
    if (source.emission)
      fail(d.range, "an area light inside an object definition (ObjectBegin) is not supported",
           "pbrt-v3 does not support it either: it drops the emission");
    current_object_->push_back(std::move(source));
    return;
  }
  place(source, world_from_pbrt_world_);
}

void Importer::mesh_from_ply(const Directive& d, ParamSet& params, ShapeSource& source) {
  const Param* filename = params.find("filename", {ParamType::string});
  if (!filename || filename->strings.size() != 1) fail(d.range, "Shape \"plymesh\" needs \"string filename\"");
  std::filesystem::path path = filename->strings[0];
  if (path.is_relative()) path = search_directory_ / path;
  std::string error;
  std::optional<std::string> bytes = options_.read_file(path, error);
  if (!bytes) fail(filename->values, "cannot read mesh '" + path.string() + "': " + error);
  PlyMesh mesh;
  try {
    mesh = parse_ply(*bytes);
  } catch (const PlyError& ply) {
    fail(filename->values, "cannot read mesh '" + path.string() + "': " + ply.what());
  }
  if (mesh.indices.empty()) fail(filename->values, "mesh '" + path.string() + "' has no triangles");
  for (const auto& p : mesh.positions) source.positions.emplace_back(p[0], p[1], p[2]);
  for (const auto& n : mesh.normals) source.normals.emplace_back(n[0], n[1], n[2]);
  source.indices = std::move(mesh.indices);
}

// Into the Scene, in world metres: meshes baked (their triangles wound so
// that an emitter emits on pbrt-v3's side), spheres as centre and radius.
void Importer::place(const ShapeSource& source, const Matrix& world_from_pbrt_world) {
  Matrix world_from_object = world_from_pbrt_world * source.object_to_pbrt_world;
  Shape shape;
  shape.material = source.material;
  if (source.emission) {
    const Rgb& l = source.emission->radiance;
    if (l[0] > 0 || l[1] > 0 || l[2] > 0)
      shape.emission = sg::from_raw<Radiance>(sg::vec3_rep(static_cast<Real>(l[0]), static_cast<Real>(l[1]),
                                                          static_cast<Real>(l[2])));
    shape.two_sided_emission = source.emission->two_sided;
  }
  if (source.kind == ShapeSource::Kind::sphere) {
    if (!is_similarity(world_from_object, 1e-4))
      fail(source.at, "a sphere under a transform that scales unevenly (an ellipsoid) is not supported");
    if (shape.emission && source.reverse_orientation && !shape.two_sided_emission)
      fail(source.at, "an emitting sphere turned inside out (ReverseOrientation) is not supported",
           "\"bool twosided\" \"true\" emits on both sides");
    shape.type = Shape::Type::sphere;
    shape.center = sg::from_raw<PointObject>(sg::vec3_rep(sg::raw(to_world_point(world_from_object, {0, 0, 0}, source.at))));
    Real radius = static_cast<Real>(source.radius * glm::length(glm::dmat3(world_from_object)[0]));
    if (!std::isfinite(radius) || !(radius > 0)) fail(source.at, "the sphere's radius is out of float range");
    shape.radius = sg::from_raw<Length>(radius);
    result_.scene.shapes.push_back(std::move(shape));
    return;
  }
  shape.type = Shape::Type::mesh;
  shape.positions.reserve(source.positions.size());
  for (const glm::dvec3& p : source.positions)
    shape.positions.push_back(sg::from_raw<PointObject>(sg::vec3_rep(sg::raw(to_world_point(world_from_object, p, source.at)))));
  shape.indices = source.indices;
  if (shape.emission) {
    // pbrt-v3 emits on the side of its geometric normal: the winding's
    // (right-handed in its world), flipped by ReverseOrientation and by a
    // mirroring object transform; with vertex normals, the side they point to.
    bool mirrored_object = determinant3(source.object_to_pbrt_world) < 0;
    bool mirrored_world = determinant3(world_from_pbrt_world) < 0;
    bool flip_all = mirrored_world != (source.reverse_orientation != mirrored_object);
    glm::dmat3 normal_to_world = glm::transpose(glm::inverse(glm::dmat3(world_from_object)));
    for (size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
      bool flip = flip_all;
      if (!source.normals.empty()) {
        const uint32_t* v = &shape.indices[t];
        glm::dvec3 n = normal_to_world * glm::dvec3(source.normals[v[0]] + source.normals[v[1]] + source.normals[v[2]]);
        glm::dvec3 a(sg::raw(shape.positions[v[0]])), b(sg::raw(shape.positions[v[1]])), c(sg::raw(shape.positions[v[2]]));
        flip = glm::dot(glm::cross(b - a, c - a), n) < 0;
      }
      if (flip) std::swap(shape.indices[t + 1], shape.indices[t + 2]);
    }
  }
  if (!source.normals.empty() && normals_warned_++ == 0)
    warn(source.at, "vertex normals \"N\" only orient emitters here: surfaces are shaded with their geometric normals",
         "pbrt-v3 interpolates them for shading: smooth meshes look faceted by comparison");
  result_.scene.shapes.push_back(std::move(shape));
}

void Importer::object_instance(const Directive& d) {
  if (current_object_) fail(d.range, "ObjectInstance inside the definition of object \"" + current_object_name_ + "\"");
  auto found = objects_.find(d.strings[0]);
  if (found == objects_.end())
    fail(d.string_ranges[0], "no object named \"" + d.strings[0] + "\"", "ObjectBegin ... ObjectEnd defines one");
  // Instances are flattened: each is a copy of the object's shapes.
  Matrix world_from_instance = world_from_pbrt_world_ * state_.ctm;
  for (const ShapeSource& source : found->second) place(source, world_from_instance);
}

}  // namespace safegi::render::pbrt
