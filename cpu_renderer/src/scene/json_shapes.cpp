#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "scene/json_loader.hpp"
#include "scene/mesh_normals.hpp"
#include "scene/ply.hpp"

namespace safegi::render::json {

Shape Loader::load_shape(const Json& value, const JsonPath& path, const std::map<std::string, int>& materials) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  static constexpr const char* common[] = {"type",      "name",      "material",          "emission",    "two_sided",
                                           "light_samples", "transform", "transform_at_close", "alpha", "shadow_alpha"};
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
    allow({"positions", "indices", "uvs", "normals"});
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
  if (value.contains("light_samples"))
    shape.emission_samples = integer(value["light_samples"], path.field("light_samples"), 1, kMaxEmitterSamples);
  // Masks, as pbrt-v3's: the surface is missing (for shadows only: casts none) where the value is 0.
  for (auto [field, mask] : {std::pair{"alpha", &shape.alpha}, std::pair{"shadow_alpha", &shape.shadow_alpha}})
    if (value.contains(field)) {
      TexturedReflectance read = textured_reflectance(value[field], path.field(field));
      if (read.textured() || sg::raw(read.value).x == 0) *mask = read;
    }
  if (value.contains("transform")) shape.render_from_object = load_transform(value["transform"], path.field("transform"));
  if (value.contains("transform_at_close"))
    shape.render_from_object_at_close = load_transform(value["transform_at_close"], path.field("transform_at_close"));
  if (shape.type == Shape::Type::sphere) {
    for (const RenderFromObject* m : {&shape.render_from_object, shape.render_from_object_at_close ? &*shape.render_from_object_at_close : nullptr}) {
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
  // Texture coordinates and normals have their own indices in OBJ: with
  // either, each distinct (position, texcoord, normal) triple becomes one
  // vertex. Each is used only when every corner of every face has one.
  const auto& texcoords = reader.GetAttrib().texcoords;
  const auto& obj_normals = reader.GetAttrib().normals;
  bool textured = !texcoords.empty(), smooth = !obj_normals.empty();
  for (const tinyobj::shape_t& obj_shape : reader.GetShapes())
    for (const tinyobj::index_t& index : obj_shape.mesh.indices) {
      textured = textured && index.texcoord_index >= 0 && 2 * static_cast<size_t>(index.texcoord_index) + 1 < texcoords.size();
      smooth = smooth && index.normal_index >= 0 && 3 * static_cast<size_t>(index.normal_index) + 2 < obj_normals.size();
    }
  std::vector<PointObject> obj_positions;
  if (textured || smooth) obj_positions.swap(shape.positions);
  std::vector<glm::dvec3> normals;
  std::map<std::array<int, 3>, uint32_t> vertex_of;
  for (const tinyobj::shape_t& obj_shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : obj_shape.mesh.indices) {
      size_t count = textured || smooth ? obj_positions.size() : shape.positions.size();
      if (index.vertex_index < 0 || static_cast<size_t>(index.vertex_index) >= count)
        fail(path.field("file"), "mesh '" + file + "' has a face with a vertex index out of range");
      if (!textured && !smooth) {
        shape.indices.push_back(static_cast<uint32_t>(index.vertex_index));
        continue;
      }
      const std::array<int, 3> key{index.vertex_index, textured ? index.texcoord_index : -1, smooth ? index.normal_index : -1};
      auto [found, inserted] = vertex_of.try_emplace(key, static_cast<uint32_t>(shape.positions.size()));
      if (inserted) {
        shape.positions.push_back(obj_positions[index.vertex_index]);
        if (textured) shape.uvs.push_back({texcoords[2 * index.texcoord_index], texcoords[2 * index.texcoord_index + 1]});
        if (smooth) {
          const float* n = &obj_normals[3 * static_cast<size_t>(index.normal_index)];
          normals.emplace_back(n[0], n[1], n[2]);
        }
      }
      shape.indices.push_back(found->second);
    }
  }
  if (shape.indices.empty() || shape.indices.size() % 3 != 0)
    fail(path.field("file"), "mesh '" + file + "' has no triangles");
  if (smooth) shape.normals = unit_vertex_normals(normals, shape.positions, shape.indices);
}

// PLY: positions, faces, and the vertex normals and texture coordinates it has.
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
  if (!mesh.normals.empty()) {
    std::vector<glm::dvec3> normals;
    for (const std::array<float, 3>& n : mesh.normals) normals.emplace_back(n[0], n[1], n[2]);
    shape.normals = unit_vertex_normals(normals, shape.positions, shape.indices);
  }
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
  if (value.contains("normals")) {
    const Json& list = value["normals"];
    JsonPath normals_path = path.field("normals");
    if (!list.is_array() || list.size() != shape.positions.size())
      fail(normals_path, "expected one [x, y, z] per position (" + std::to_string(shape.positions.size()) + ")");
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_array() || list[i].size() != 3) fail(normals_path.index(i), "expected [x, y, z], got " + short_dump(list[i]));
      glm::dvec3 n;
      for (int axis = 0; axis < 3; ++axis) n[axis] = number(list[i][axis], normals_path.index(i).index(axis), -1e6, 1e6);
      if (!(glm::length(n) > 0)) fail(normals_path.index(i), "a normal needs a direction, got [0, 0, 0]");
      normals.push_back(n);
    }
    shape.normals = unit_vertex_normals(normals, shape.positions, shape.indices);
  }
}

}  // namespace safegi::render::json
