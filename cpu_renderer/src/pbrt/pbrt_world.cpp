// The importer's world block: attributes, lights, shapes and object instances
// (pbrt-v3's core/api.cpp, mapped onto our Scene); materials and textures are
// in pbrt_materials.cpp.
#include <array>
#include <cmath>

#include "scene/mesh_normals.hpp"
#include "pbrt/pbrt_importer.hpp"
#include "scene/ply.hpp"

namespace safegi::render::pbrt {

namespace {

// A material with an outside (pbrt-v3's: its geometric normal's side; ours:
// the winding's): glass, and translucent's glossy lobes, whose interface has
// index 1.5 inside; disney, whose Fresnel terms and refraction see index eta
// inside; pbrt-v3's plastic, whose swapped Fresnel indices hold on
// that side only (with `plastic`); a mix with any of them among its parts.
bool has_outside(const Scene& scene, int index, bool plastic = true) {
  if (index < 0) return false;
  const Material& material = scene.materials[index];
  if (material.mix)
    return has_outside(scene, material.mix->first, plastic) || has_outside(scene, material.mix->second, plastic);
  // (A glass of index 1, uber's transparent part, bends nothing: it has no outside.)
  return std::visit(Overloaded{[](const GlassMaterial& g) { return g.ior != 1; },
                               [](const TranslucentMaterial& t) { return !sg::is_black(t.specular); },
                               [](const DisneyMaterial& d) { return d.eta != 1; },
                               [&](const PlasticMaterial& p) { return plastic && p.pbrt_v3_fresnel; },
                               [](const auto&) { return false; }},
                    material.model);
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

// An orthogonal matrix (a rotation, perhaps mirroring) as a typed map; its inverse is its transpose.
template <class Map>
Map orthogonal_map(const glm::dmat3& r) {
  return sg::from_raw<Map>(sg::matrix_pair{sg::mat4_rep(sg::mat3_rep(r)), sg::mat4_rep(sg::mat3_rep(glm::transpose(r)))});
}

TexCoord texture_coordinate(double u, double v, SourceRange at) {
  TexCoord t{static_cast<Real>(u), static_cast<Real>(v)};
  if (!std::isfinite(t.u) || !std::isfinite(t.v)) fail(at, std::string("a texture coordinate is out of ") + kRealName + " range");
  return t;
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
    transform_stack_.push_back(state_.transform);
  } else if (name == "AttributeEnd" || name == "ObjectEnd") {
    if (name == "ObjectEnd") {
      if (!current_object_) fail(d.range, "ObjectEnd without ObjectBegin");
      current_object_ = nullptr;
    }
    if (attribute_stack_.empty() || transform_stack_.empty())
      fail(d.range, name + " without a matching " + (name == "ObjectEnd" ? "ObjectBegin" : "AttributeBegin"));
    state_ = std::move(attribute_stack_.back());
    attribute_stack_.pop_back();
    state_.transform = transform_stack_.back();
    transform_stack_.pop_back();
  } else if (name == "TransformBegin") {
    transform_stack_.push_back(state_.transform);
  } else if (name == "TransformEnd") {
    if (transform_stack_.empty()) fail(d.range, "TransformEnd without a matching TransformBegin");
    state_.transform = transform_stack_.back();
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
    finish_media(d.range);
    block_ = Block::ended;
  } else if (name == "WorldBegin") {
    fail(d.range, "a second WorldBegin", "a scene file renders one image: one WorldBegin ... WorldEnd block");
  } else {
    fail(d.range, name + " is not supported inside the world block");
  }
}

// ---------------------------------------------------------------------------
// Lights

void Importer::light_source(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "LightSource \"" + type + "\"");
  if (state_.transform.animated())
    warn(d.range, "an animated light is placed by its start transform", "pbrt-v3 does the same (and warns)");
  if (type == "point" || type == "spot" || type == "goniometric" || type == "projection") {
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
    if (type == "goniometric" || type == "projection") {
      result_.scene.point_lights.push_back(mapped_point_light(d, params, intensity));
      report_unused(params);
      return;
    }
    Triple from = params.one_point("from").value_or(Triple{0, 0, 0});
    glm::dvec3 from_v(from[0], from[1], from[2]);
    if (type == "point") {
      // pbrt-v3 offsets "from" in world space: Translate(from) * CTM.
      glm::dvec3 at = glm::dvec3(state_.transform.start * glm::dvec4(0, 0, 0, 1)) + from_v;
      result_.scene.point_lights.push_back({to_world_point(world_from_pbrt_world_, at, d.range), intensity});
    } else {
      Triple to = params.one_point("to").value_or(Triple{0, 0, 1});
      glm::dvec3 axis = glm::dvec3(to[0], to[1], to[2]) - from_v;
      if (!(glm::length(axis) > 0)) fail(d.range, "the spot light's \"from\" and \"to\" coincide");
      // Its position and direction are pbrt-v3's under any transform; only its cone would be elliptic.
      const double deviation = deviation_from_similarity(glm::dmat3(state_.transform.start));
      if (deviation > kRoundedSimilarity)
        fail(d.range, "a spot light under a transform that scales unevenly or shears is not supported",
             "it would make the cone elliptic");
      warn_if_rounded(d.range, "the spot light's transform", deviation);
      Matrix m = world_from_pbrt_world_ * state_.transform.start;
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
  } else if (type == "infinite" || type == "exinfinite") {
    infinite_light(d, params);
  } else if (type == "distant") {
    distant_light(d, params);
  } else {
    fail(d.string_ranges[0], "light \"" + type + "\" is not supported",
         "supported: \"point\", \"spot\", \"goniometric\", \"projection\", \"distant\", \"infinite\"");
  }
  report_unused(params);
}

namespace {

// The mesh's vertex normals "N" through `normals_from_object` (an inverse
// transpose) beside the shape's positions in its object space.
std::vector<normal<Object>> shading_normals(const ShapeSource& source, const glm::dmat3& normals_from_object, const Shape& shape) {
  std::vector<glm::dvec3> placed;
  placed.reserve(source.normals.size());
  for (const glm::dvec3& n : source.normals) placed.push_back(normals_from_object * n);
  return unit_vertex_normals(placed, shape.positions, shape.indices);
}

// A distant or infinite light's "L" × "scale" (each 1 by default), none negative.
Rgb scaled_output(ParamSet& params) {
  Rgb output{1, 1, 1};
  for (const char* name : {"L", "scale"})
    if (std::optional<SpectrumValue> value = params.spectrum(name, false))
      for (int c = 0; c < 3; ++c) {
        if (!(value->rgb[c] >= 0)) params.fail_at(*value->param, "light output must not be negative");
        output[c] *= value->rgb[c];
      }
  return output;
}

// A light's "string mapname", or nullptr without one: pbrt-v3 reads an empty
// name as no map (exporters write `"string mapname" [ "" ]` for none).
const Param* light_map_name(ParamSet& params) {
  const Param* map = params.find("mapname", {ParamType::string});
  if (!map) return nullptr;
  if (map->strings.size() != 1) fail(map->values, "\"string mapname\" takes 1 value");
  return map->strings[0].empty() ? nullptr : map;
}

}  // namespace

// pbrt-v3's DistantLight: irradiance L × scale on a surface facing it (read
// as W/m², which keeps pbrt's pixel values), arriving from the direction
// from − to under the transform at the directive.
void Importer::distant_light(const Directive& d, ParamSet& params) {
  Rgb irradiance = scaled_output(params);
  Triple from = params.one_point("from").value_or(Triple{0, 0, 0}), to = params.one_point("to").value_or(Triple{0, 0, 1});
  glm::dvec3 towards(from[0] - to[0], from[1] - to[1], from[2] - to[2]);
  if (!(glm::length(towards) > 0)) fail(d.range, "the distant light's \"from\" and \"to\" coincide");
  // As pbrt-v3 maps it: a vector through the transform (LightToWorld(w)).
  glm::dvec3 direction = glm::dmat3(world_from_pbrt_world_ * state_.transform.start) * towards;
  if (!(glm::length(direction) > 0) || !std::isfinite(glm::length(direction)))
    fail(d.range, "the distant light's direction is not finite under its transform");
  DistantLight light;
  light.direction = sg::normalize(sg::from_raw<vector<World, dim::dimensionless>>(sg::vec3_rep(glm::normalize(direction))));
  light.irradiance = sg::from_raw<spectrum<dim::irradiance>>(
      sg::vec3_rep(static_cast<Real>(irradiance[0]), static_cast<Real>(irradiance[1]), static_cast<Real>(irradiance[2])));
  sg::vec3_rep rgb = sg::raw(light.irradiance);
  if (!std::isfinite(rgb.x) || !std::isfinite(rgb.y) || !std::isfinite(rgb.z))
    fail(d.range, std::string("the distant light's irradiance is out of ") + kRealName + " range");
  result_.scene.distant_lights.push_back(light);
}

// pbrt-v3's InfiniteAreaLight: L × scale, times the lat-long map's texels
// (read as they are: pbrt-v3 decodes no gamma here), in light space, which its
// transform at the directive maps to the world. Our EnvironmentLight has the
// same layout (u = φ/2π, v = θ/π, row 0 at +z); the world's mirroring (when
// the camera needs it) goes into render_from_light, an orthogonal map.
void Importer::infinite_light(const Directive& d, ParamSet& params) {
  if (environment_at_)
    fail(d.string_ranges[0], "a second infinite light",
         "the renderer has one environment light per scene (the first is at line " +
             std::to_string(environment_at_->begin.line) + ")");
  Rgb radiance = scaled_output(params);
  EnvironmentLight light;
  light.radiance = sg::from_raw<Radiance>(sg::vec3_rep(static_cast<Real>(radiance[0]), static_cast<Real>(radiance[1]),
                                                      static_cast<Real>(radiance[2])));
  sg::vec3_rep rgb = sg::raw(light.radiance);
  if (!std::isfinite(rgb.x) || !std::isfinite(rgb.y) || !std::isfinite(rgb.z))
    fail(d.range, std::string("the infinite light's radiance is out of ") + kRealName + " range");
  // Shadow rays per shading point under pbrt's directlighting (its "all" strategy).
  const int samples = params.one_int("samples", params.one_int("nsamples", 1, 1, 1 << 20), 1, 1 << 20);
  light.samples = light_samples_per_light_ ? std::min(samples, kMaxEmitterSamples) : 1;
  if (const Param* map = light_map_name(params)) {
    light.file = map->strings[0];
    light.map = std::make_shared<MipMap>(read_image(*map), TextureWrap::longitude_latitude);
  }
  const Matrix world_from_light = world_from_pbrt_world_ * state_.transform.start;
  light.render_from_light = orthogonal_map<RenderFromLight>(light_rotation(world_from_light, d.range, "infinite"));
  result_.scene.environment = std::move(light);
  environment_at_ = d.string_ranges[0];
}

// The rotation (or mirroring) of a light whose map turns with its transform
// `m` (world ← light): a uniform scale changes no direction; a transform off a
// scaled rotation by rounding only (an exporter's) is taken as the nearest one,
// with a warning; one that distorts the map is refused.
glm::dmat3 Importer::light_rotation(const Matrix& m, SourceRange at, const std::string& type) {
  const double deviation = deviation_from_similarity(glm::dmat3(m));
  if (deviation > kRoundedSimilarity)
    fail(at, std::string(type == "infinite" ? "an " : "a ") + type +
                 " light under a transform that scales unevenly or shears is not supported",
         "it would distort the map; rotate it only");
  warn_if_rounded(at, "the " + type + " light's transform", deviation);
  const glm::dmat3 similarity = nearest_similarity(glm::dmat3(m));
  return similarity / glm::length(similarity[0]);
}

// pbrt-v3's goniometric and projection lights: a point light at the light
// transform's origin, its intensity shaped by a map in the light's frame
// (IntensityMap). Without "mapname" pbrt-v3 uses texels of 1, and so do we.
PointLight Importer::mapped_point_light(const Directive& d, ParamSet& params, Intensity intensity) {
  const std::string& type = d.strings[0];
  const bool projection = type == "projection";
  Matrix m = world_from_pbrt_world_ * state_.transform.start;
  const glm::dmat3 rotation = light_rotation(m, d.range, type);
  IntensityMap profile;
  profile.layout = projection ? IntensityMap::Layout::projection : IntensityMap::Layout::goniometric;
  if (projection) {
    double fov = params.one_float("fov", 45);
    if (!(fov > 0 && fov < 180)) fail(d.range, "\"float fov\" must lie in (0, 180) degrees");
    profile.fov = static_cast<Real>(fov) * units::degree;
  }
  if (const Param* map = light_map_name(params)) {
    profile.file = map->strings[0];
    profile.map = std::make_shared<MipMap>(read_image(*map), projection ? TextureWrap::clamp : TextureWrap::longitude_latitude);
  }
  profile.render_from_light = orthogonal_map<RenderFromLight>(rotation);
  return {to_world_point(m, {0, 0, 0}, d.range), intensity, std::move(profile)};
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
  // Shadow rays per light for pbrt's direct-lighting integrator (its "all"
  // strategy); every other integrator takes one.
  light.samples = params.one_int("samples", params.one_int("nsamples", 1, 1, 1 << 20), 1, 1 << 20);
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
  source.pbrt_world_from_object = state_.transform.start;
  if (state_.transform.animated()) source.pbrt_world_from_object_at_end = state_.transform.end;
  source.reverse_orientation = state_.reverse_orientation;
  auto read_alpha_masks = [&] {
    source.alpha = alpha_mask(params, "alpha");
    source.shadow_alpha = alpha_mask(params, "shadowalpha");
  };
  if (type == "trianglemesh") {
    source.kind = ShapeSource::Kind::mesh;
    const Param* p = params.find("P", {ParamType::point3});
    if (!p) fail(d.range, "Shape \"trianglemesh\" needs \"point P\" (its vertices)");
    const Param* indices = params.find("indices", {ParamType::integer});
    if (p->numbers.empty() || (indices && indices->numbers.empty())) {
      // Exporters write meshes of nothing (Blender: `"point P" [ ]`); pbrt-v3 makes no shape of one and goes on.
      warn(d.string_ranges[0],
           std::string("an empty triangle mesh (no ") + (p->numbers.empty() ? "\"point P\"" : "\"integer indices\"") +
               ") makes nothing",
           "pbrt-v3 makes nothing of it either");
      params.ignore_the_rest();
      return;
    }
    if (p->numbers.size() % 3 != 0)
      fail(p->values, "\"point P\" takes x y z per vertex: " + std::to_string(p->numbers.size()) + " numbers");
    for (size_t i = 0; i < p->numbers.size(); i += 3)
      source.positions.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
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
    // Texture coordinates: "uv", or without it "st" (pbrt-v3's order).
    const Param* uv = params.find("uv", {ParamType::floating, ParamType::point2});
    if (!uv) uv = params.find("st", {ParamType::floating, ParamType::point2});
    if (uv) {
      if (uv->numbers.size() != 2 * source.positions.size())
        fail(uv->values, "\"" + uv->type_name + " " + uv->name + "\" needs one (u, v) pair per vertex of \"point P\": " +
                             std::to_string(uv->numbers.size()) + " values for " + std::to_string(source.positions.size()) +
                             " vertices");
      for (size_t i = 0; i < uv->numbers.size(); i += 2) source.uvs.push_back(texture_coordinate(uv->numbers[i], uv->numbers[i + 1], uv->values));
    }
    // Tangents and face ids: nothing here reads them.
    params.find("S", {ParamType::vector3});
    params.find("faceIndices", {ParamType::integer});
    read_alpha_masks();
  } else if (type == "plymesh") {
    source.kind = ShapeSource::Kind::mesh;
    mesh_from_ply(d, params, source);
    params.reject("displacement", "displacement mapping");
    params.one_float("edgelength", 1);
    read_alpha_masks();
  } else if (type == "sphere") {
    double radius = params.one_float("radius", 1);
    if (!(radius > 0)) fail(d.range, "a sphere's \"float radius\" must be positive");
    // Scaled unevenly, an ellipsoid: a mesh (the renderer's spheres are round).
    const bool ellipsoid = !is_similarity(state_.transform.start, 1e-4);
    if (sphere_mesh(radius, ellipsoid, params, d.string_ranges[0], source)) {
      source.kind = ShapeSource::Kind::mesh;
    } else {
      source.kind = ShapeSource::Kind::sphere;
      source.radius = radius;
    }
  } else if (const SourceRange name = d.string_ranges[0];
             quadric_mesh(type, params, name, source) || nurbs_mesh(type, params, name, source) ||
             heightfield_mesh(type, params, name, source) || loopsubdiv_mesh(type, params, name, source)) {
    source.kind = ShapeSource::Kind::mesh;
  } else if (curve_mesh(type, params, d.string_ranges[0], source, curve_triangles_)) {
    source.kind = ShapeSource::Kind::mesh;
    if (params.one_string("type", "flat") == "flat")
      warn(d.string_ranges[0], "a flat curve is rendered as a tube of its width",
           "pbrt-v3 turns a flat curve to face each ray: the same silhouette, shaded as a strip facing the viewer, "
           "where a tube is shaded round (\"string type\" \"cylinder\" is the tube pbrt-v3 fakes)");
  } else {
    fail(d.string_ranges[0], "shape \"" + type + "\" is not supported",
         "supported: \"trianglemesh\", \"plymesh\", \"sphere\", \"disk\", \"cylinder\", \"cone\", "
         "\"paraboloid\", \"hyperboloid\", \"nurbs\", \"heightfield\", \"loopsubdiv\", \"curve\"");
  }
  // pbrt-v3's quadrics are one shape each; its meshes, nurbs and subdivision surfaces, triangles.
  if (type == "trianglemesh" || type == "plymesh" || type == "nurbs" || type == "heightfield" ||
      type == "loopsubdiv")
    source.pbrt_lights = static_cast<int>(std::min<size_t>(source.indices.size() / 3, 1 << 30));
  source.material = material_index(*state_.material, params);
  source.invisible = state_.material->invisible;
  source.media = shape_media();
  source.emission = state_.area_light;
  report_unused(params);
  if (source.pbrt_world_from_object_at_end) {
    if (current_object_)
      fail(d.range, "an animated shape inside an object definition (ObjectBegin) is not supported");
    if (source.emission) {
      // pbrt-v3's pbrtShape: "Ignoring currently set area light when creating animated shape".
      warn(d.range, "an animated shape does not emit: its area light is ignored", "pbrt-v3 ignores it too");
      source.emission.reset();
    }
    if (!motion_at_) motion_at_ = d.range;
  }
  if (current_object_) {
    if (source.emission)
      fail(d.range, "an area light inside an object definition (ObjectBegin) is not supported",
           "pbrt-v3 does not support it either: it drops the emission");
    current_object_->push_back(std::move(source));
    return;
  }
  place(source, world_from_pbrt_world_);
}

// pbrt-v3's "alpha" and "shadowalpha" of a triangle mesh: a float or a float
// texture, which masks the surface only where it is exactly 0; a constant
// other than 0 (1 by default) is no mask.
std::optional<TexturedReflectance> Importer::alpha_mask(ParamSet& params, const char* name) {
  const Param* param = nullptr;
  std::optional<TextureEntry> entry = float_or_texture(params, name, param);
  if (!entry || (!entry->textured() && entry->value[0] != 0)) return std::nullopt;
  TexturedReflectance mask;
  mask.value = Reflectance(static_cast<Real>(entry->value[0]));
  mask.texture = entry->image;
  mask.pattern = entry->pattern;
  return mask;
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
  for (const auto& uv : mesh.uvs) source.uvs.push_back(texture_coordinate(uv[0], uv[1], filename->values));
  source.indices = std::move(mesh.indices);
}

// Into the Scene, in world metres: meshes baked (their triangles wound so
// that an emitter emits on pbrt-v3's side), spheres as centre and radius.
void Importer::place(const ShapeSource& source, const Matrix& world_from_pbrt_world) {
  Matrix world_from_object = world_from_pbrt_world * source.pbrt_world_from_object;
  Shape shape;
  shape.material = source.material;
  shape.invisible = source.invisible;
  shape.alpha = source.alpha;
  shape.shadow_alpha = source.shadow_alpha;
  shape.media = source.media;
  if (source.emission) {
    const Rgb& l = source.emission->radiance;
    if (l[0] > 0 || l[1] > 0 || l[2] > 0)
      shape.emission = sg::from_raw<Radiance>(sg::vec3_rep(static_cast<Real>(l[0]), static_cast<Real>(l[1]),
                                                          static_cast<Real>(l[2])));
    shape.two_sided_emission = source.emission->two_sided;
    // Under LightStrategy::all, as many shadow rays as pbrt-v3's directlighting
    // takes for the lights it makes of this shape (one per triangle of a mesh).
    const int64_t samples = static_cast<int64_t>(light_samples_per_light_ ? source.emission->samples : 1) * source.pbrt_lights;
    shape.emission_samples = static_cast<int>(std::clamp<int64_t>(samples, 1, kMaxEmitterSamples));
  }
  const bool sided = has_outside(result_.scene, shape.material);
  if (source.kind == ShapeSource::Kind::sphere) {
    if (!is_similarity(world_from_object, 1e-4))
      fail(source.at, "a sphere under an object instance's transform that scales unevenly (an ellipsoid) is not supported",
           "scale the sphere itself, inside ObjectBegin, and it becomes a mesh");
    if (shape.emission && source.reverse_orientation && !shape.two_sided_emission)
      fail(source.at, "an emitting sphere turned inside out (ReverseOrientation) is not supported",
           "\"bool twosided\" \"true\" emits on both sides");
    // (A plastic one keeps the swapped Fresnel on its outside: pbrt-v3's has it on the inside.)
    if (source.reverse_orientation && has_outside(result_.scene, shape.material, false))
      fail(source.at, "a glass, translucent or disney sphere turned inside out (ReverseOrientation) is not supported",
           "its outside would be the inside of the sphere");
    // Our sphere's normal points out; pbrt-v3's, in, under ReverseOrientation.
    if (shape.media && source.reverse_orientation) std::swap(shape.media->inside, shape.media->outside);
    // Centre and radius in world metres; the object frame's rotation (and
    // mirroring) kept in render_from_object, where the sphere's (u, v) are pbrt's.
    shape.type = Shape::Type::sphere;
    const double scale = glm::length(glm::dmat3(world_from_object)[0]);
    const glm::dmat3 rotation = glm::dmat3(world_from_object) / scale;
    shape.render_from_object = orthogonal_map<RenderFromObject>(rotation);
    glm::dvec3 centre = glm::transpose(rotation) * glm::dvec3(sg::raw(to_world_point(world_from_object, {0, 0, 0}, source.at)));
    shape.center = sg::from_raw<PointObject>(sg::vec3_rep(centre));
    Real radius = static_cast<Real>(source.radius * scale);
    if (!std::isfinite(radius) || !(radius > 0)) fail(source.at, std::string("the sphere's radius is out of ") + kRealName + " range");
    shape.radius = sg::from_raw<Length>(radius);
    if (source.pbrt_world_from_object_at_end) animate(source, world_from_pbrt_world, shape);
    result_.scene.shapes.push_back(std::move(shape));
    return;
  }
  shape.type = Shape::Type::mesh;
  shape.positions.reserve(source.positions.size());
  for (const glm::dvec3& p : source.positions)
    shape.positions.push_back(sg::from_raw<PointObject>(sg::vec3_rep(sg::raw(to_world_point(world_from_object, p, source.at)))));
  shape.indices = source.indices;
  shape.uvs = source.uvs;
  const glm::dmat3 world_from_object_normals = glm::transpose(glm::inverse(glm::dmat3(world_from_object)));
  shape.normals = shading_normals(source, world_from_object_normals, shape);
  if (shape.emission || sided || shape.media) {
    // pbrt-v3 emits on the side of its geometric normal, and has glass's
    // outside there (our glass: on the winding's side), and a medium
    // interface's outside medium: the winding's
    // (right-handed in its world), flipped by ReverseOrientation and by a
    // mirroring object transform; with vertex normals, the side they point to.
    bool mirrored_object = determinant3(source.pbrt_world_from_object) < 0;
    bool mirrored_world = determinant3(world_from_pbrt_world) < 0;
    bool flip_all = mirrored_world != (source.reverse_orientation != mirrored_object);
    for (size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
      bool flip = flip_all;
      if (!source.normals.empty()) {
        const uint32_t* v = &shape.indices[t];
        glm::dvec3 n = world_from_object_normals * glm::dvec3(source.normals[v[0]] + source.normals[v[1]] + source.normals[v[2]]);
        glm::dvec3 a(sg::raw(shape.positions[v[0]])), b(sg::raw(shape.positions[v[1]])), c(sg::raw(shape.positions[v[2]]));
        flip = glm::dot(glm::cross(b - a, c - a), n) < 0;
      }
      if (flip) std::swap(shape.indices[t + 1], shape.indices[t + 2]);
    }
  }
  if (source.pbrt_world_from_object_at_end) animate(source, world_from_pbrt_world, shape);
  result_.scene.shapes.push_back(std::move(shape));
}

// A shape that moves (ActiveTransform): kept in object space with its poses at
// shutter open and close, which the renderer interpolates as pbrt-v3's
// AnimatedTransform does (translation and scale linearly, rotation slerped).
// Where the world mirrors (pbrt-v3's left-handed world in ours), both poses are
// taken times a mirror F in object space and the points times F: F·F = 1 keeps
// every point where it was, each pose is a rotation again, and interpolating
// W·C·F is W·(interpolated C)·F, pbrt-v3's motion mirrored.
void Importer::animate(const ShapeSource& source, const Matrix& world_from_pbrt_world, Shape& shape) {
  const Matrix at_open = world_from_pbrt_world * source.pbrt_world_from_object;
  const Matrix at_close = world_from_pbrt_world * *source.pbrt_world_from_object_at_end;
  const bool mirrored = determinant3(at_open) < 0;
  if (mirrored != (determinant3(at_close) < 0))
    fail(source.at, "a shape whose animated transform mirrors it at one time only is not supported");
  if (source.kind == ShapeSource::Kind::sphere && !is_similarity(at_close, 1e-4))
    fail(source.at, "a sphere whose animated transform scales it unevenly is not supported");
  Matrix mirror(1.0);
  if (mirrored) mirror[0][0] = -1;
  auto pose = [&](const Matrix& m) {
    const sg::mat4_rep rep(m * mirror);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(rep[c][r]))
          fail(source.at, std::string("the shape's animated transform is out of ") + kRealName + " range");
    return RenderFromObject::from_matrix(rep);
  };
  shape.render_from_object = pose(at_open);
  shape.render_from_object_at_close = pose(at_close);
  if (shape.type == Shape::Type::sphere) {
    shape.center = sg::from_raw<PointObject>(sg::vec3_rep(0, 0, 0));
    shape.radius = sg::from_raw<Length>(static_cast<Real>(source.radius));
    return;
  }
  for (size_t i = 0; i < source.positions.size(); ++i) {
    const glm::dvec3 p = glm::dvec3(mirror * glm::dvec4(source.positions[i], 1));
    shape.positions[i] = sg::from_raw<PointObject>(sg::vec3_rep(static_cast<Real>(p.x), static_cast<Real>(p.y), static_cast<Real>(p.z)));
  }
  if (!shape.normals.empty()) shape.normals = shading_normals(source, glm::dmat3(mirror), shape);  // a mirror is its own inverse transpose
}

void Importer::object_instance(const Directive& d) {
  if (current_object_) fail(d.range, "ObjectInstance inside the definition of object \"" + current_object_name_ + "\"");
  auto found = objects_.find(d.strings[0]);
  if (found == objects_.end())
    fail(d.string_ranges[0], "no object named \"" + d.strings[0] + "\"", "ObjectBegin ... ObjectEnd defines one");
  // Instances are flattened: each is a copy of the object's shapes.
  if (state_.transform.animated())
    fail(d.range, "an animated ObjectInstance is not supported", "animate the shapes of the object one by one");
  Matrix world_from_instance = world_from_pbrt_world_ * state_.transform.start;
  for (const ShapeSource& source : found->second) place(source, world_from_instance);
}

}  // namespace safegi::render::pbrt
