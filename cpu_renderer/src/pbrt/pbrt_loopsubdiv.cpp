// pbrt-v3's "loopsubdiv" shape (src/shapes/loopsubdiv.cpp) as the triangle
// mesh pbrt-v3 itself makes of it: the control mesh Loop-subdivided "levels"
// times, every vertex then moved to its limit position, with pbrt-v3's limit
// normals as the mesh's "N". The port keeps pbrt-v3's walks and orderings
// (vertex and face order, the face each vertex's ring starts from), so it is
// pbrt-v3's mesh vertex for vertex, computed in double where pbrt-v3 uses float.
//
// Control meshes pbrt-v3 crashes on (a vertex in no triangle), may loop on
// or subdivides into nonsense (a triangle repeating a vertex, an edge of more
// than two triangles, two triangles running along their shared edge the same
// way: its walks around a vertex assume none of these) are refused here.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "pbrt/pbrt_importer.hpp"
#include "safegi/cpu_renderer/memory_estimate.hpp"

namespace safegi::render::pbrt {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// The renderer indexes vertices and triangles with 32 bits; from the first
// level on a Loop mesh has at most 1.5 vertices per triangle (a lone triangle
// split in four has 6), so 2^31 triangles keep both in range.
constexpr uint64_t kMaxTriangles = uint64_t{1} << 31;

constexpr int next(int i) { return (i + 1) % 3; }
constexpr int prev(int i) { return (i + 2) % 3; }

struct Face {
  std::array<uint32_t, 3> v{};                      // its vertices, in the order the indices give them
  std::array<uint32_t, 3> f{kNone, kNone, kNone};  // f[i]: the neighbour across v[i] → v[next(i)]; kNone on a boundary
};

struct Vertex {
  glm::dvec3 p{0.0};
  uint32_t start_face = kNone;  // where walks around it start (pbrt-v3's startFace)
  bool regular = false, boundary = false;
};

// What subdividing holds per triangle of the result at its peak (the last
// level's faces and vertices, about half as many vertices as faces, beside the
// level before it, a quarter of that), then the imported mesh's positions,
// normals and indices here and in the Scene.
constexpr uint64_t kImportBytesPerTriangle = (sizeof(Face) + sizeof(Vertex) / 2) * 5 / 4 + sizeof(uint32_t) +
                                             sizeof(glm::dvec3) + 3 * sizeof(uint32_t) + sizeof(glm::vec3) / 2 +
                                             3 * sizeof(uint32_t);

// One level of the subdivision: pbrt-v3's SDVertex/SDFace graph with indices
// for pointers. Face i's children at the next level are 4i … 4i + 3 (pbrt-v3's
// children[0..3]); an old vertex's child keeps its index, the new edge
// vertices follow.
struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<Face> faces;

  int corner(uint32_t face, uint32_t vertex) const {
    const Face& f = faces[face];
    return f.v[0] == vertex ? 0 : f.v[1] == vertex ? 1 : 2;
  }
  uint32_t next_face(uint32_t face, uint32_t vertex) const { return faces[face].f[corner(face, vertex)]; }
  uint32_t prev_face(uint32_t face, uint32_t vertex) const { return faces[face].f[prev(corner(face, vertex))]; }
  uint32_t next_vertex(uint32_t face, uint32_t vertex) const { return faces[face].v[next(corner(face, vertex))]; }
  uint32_t prev_vertex(uint32_t face, uint32_t vertex) const { return faces[face].v[prev(corner(face, vertex))]; }
  uint32_t other_vertex(uint32_t face, uint32_t a, uint32_t b) const {
    const Face& f = faces[face];
    return f.v[0] != a && f.v[0] != b ? f.v[0] : f.v[1] != a && f.v[1] != b ? f.v[1] : f.v[2];
  }

  // The number of its neighbours. The walks end: with every edge in at most
  // two triangles wound alike, "the next face around a vertex" is one-to-one.
  int valence(uint32_t vertex) const {
    const uint32_t start = vertices[vertex].start_face;
    int faces_around = 1;
    if (!vertices[vertex].boundary) {
      for (uint32_t f = next_face(start, vertex); f != start; f = next_face(f, vertex)) ++faces_around;
      return faces_around;
    }
    for (uint32_t f = next_face(start, vertex); f != kNone; f = next_face(f, vertex)) ++faces_around;
    for (uint32_t f = prev_face(start, vertex); f != kNone; f = prev_face(f, vertex)) ++faces_around;
    return faces_around + 1;
  }

  // Its neighbours' positions in pbrt-v3's order; on a boundary, from one
  // boundary neighbour (ring.front()) to the other (ring.back()).
  void one_ring(uint32_t vertex, std::vector<glm::dvec3>& ring) const {
    ring.clear();
    uint32_t face = vertices[vertex].start_face;
    if (!vertices[vertex].boundary) {
      do {
        ring.push_back(vertices[next_vertex(face, vertex)].p);
        face = next_face(face, vertex);
      } while (face != vertices[vertex].start_face);
      return;
    }
    for (uint32_t f = next_face(face, vertex); f != kNone; f = next_face(f, vertex)) face = f;
    ring.push_back(vertices[next_vertex(face, vertex)].p);
    do {
      ring.push_back(vertices[prev_vertex(face, vertex)].p);
      face = prev_face(face, vertex);
    } while (face != kNone);
  }
};

double beta(int valence) { return valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * valence); }
double loop_gamma(int valence) { return 1.0 / (valence + 3.0 / (8.0 * beta(valence))); }

glm::dvec3 weight_one_ring(const Mesh& mesh, uint32_t vertex, double weight, std::vector<glm::dvec3>& ring) {
  mesh.one_ring(vertex, ring);
  glm::dvec3 p = (1 - static_cast<double>(ring.size()) * weight) * mesh.vertices[vertex].p;
  for (const glm::dvec3& q : ring) p += weight * q;
  return p;
}

glm::dvec3 weight_boundary(const Mesh& mesh, uint32_t vertex, double weight, std::vector<glm::dvec3>& ring) {
  mesh.one_ring(vertex, ring);
  return (1 - 2 * weight) * mesh.vertices[vertex].p + weight * ring.front() + weight * ring.back();
}

std::string listed(const std::vector<uint32_t>& numbers) {
  std::string text;
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (i > 0) text += i + 1 == numbers.size() ? " and " : ", ";
    text += std::to_string(numbers[i]);
  }
  return text;
}

// pbrt-v3 pairs faces by their shared edges; it cannot subdivide an edge of
// three or more faces, nor one its two faces run along the same way.
void link_neighbours(Mesh& mesh, SourceRange at) {
  struct EdgeUse {
    uint32_t low, high, face;
    int edge;
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.faces.size());
  for (uint32_t face = 0; face < mesh.faces.size(); ++face)
    for (int edge = 0; edge < 3; ++edge) {
      const uint32_t a = mesh.faces[face].v[edge], b = mesh.faces[face].v[next(edge)];
      uses.push_back({std::min(a, b), std::max(a, b), face, edge});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.low, x.high, x.face, x.edge) < std::tie(y.low, y.high, y.face, y.edge);
  });
  for (size_t i = 0; i < uses.size();) {
    size_t end = i + 1;
    while (end < uses.size() && uses[end].low == uses[i].low && uses[end].high == uses[i].high) ++end;
    const std::string edge = "vertices " + std::to_string(uses[i].low) + " and " + std::to_string(uses[i].high);
    if (end - i > 2) {
      std::vector<uint32_t> faces;
      for (size_t k = i; k < end; ++k) faces.push_back(uses[k].face);
      fail(at, "Shape \"loopsubdiv\": the edge between " + edge + " belongs to " + std::to_string(end - i) +
                   " triangles (" + listed(faces) + ")",
           "pbrt-v3 subdivides only meshes whose every edge belongs to one or two triangles");
    }
    if (end - i == 2) {
      const EdgeUse& first = uses[i];
      const EdgeUse& second = uses[i + 1];
      Face& a = mesh.faces[first.face];
      Face& b = mesh.faces[second.face];
      if (a.v[first.edge] == b.v[second.edge])
        fail(at, "Shape \"loopsubdiv\": triangles " + std::to_string(first.face) + " and " + std::to_string(second.face) +
                     " both run from vertex " + std::to_string(a.v[first.edge]) + " to vertex " +
                     std::to_string(a.v[next(first.edge)]),
             "pbrt-v3 subdivides only meshes whose neighbouring triangles are wound the same way");
      a.f[first.edge] = second.face;
      b.f[second.edge] = first.face;
    }
    i = end;
  }
}

// pbrt-v3's starting mesh: each vertex starts its walks at the last face that
// holds it; boundary and regular (valence 6 inside, 4 on a boundary) as its walk finds them.
Mesh control_mesh(std::vector<glm::dvec3> points, const std::vector<uint32_t>& indices, SourceRange at) {
  Mesh mesh;
  mesh.vertices.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) mesh.vertices[i].p = points[i];
  mesh.faces.resize(indices.size() / 3);
  for (uint32_t face = 0; face < mesh.faces.size(); ++face)
    for (int j = 0; j < 3; ++j) {
      mesh.faces[face].v[j] = indices[3 * face + j];
      mesh.vertices[indices[3 * face + j]].start_face = face;
    }
  link_neighbours(mesh, at);
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    Vertex& vertex = mesh.vertices[i];
    uint32_t face = vertex.start_face;
    do face = mesh.next_face(face, i);
    while (face != kNone && face != vertex.start_face);
    vertex.boundary = face == kNone;
    vertex.regular = mesh.valence(i) == (vertex.boundary ? 4 : 6);
  }
  return mesh;
}

// The new vertex on each face's edge k (index 3·face + k), each made once, by
// the first face that has its edge (pbrt-v3's edgeVerts), with the edge rules.
std::vector<uint32_t> add_edge_vertices(const Mesh& mesh, Mesh& child) {
  std::vector<uint32_t> edge_vertex(3 * mesh.faces.size(), kNone);
  for (uint32_t i = 0; i < mesh.faces.size(); ++i) {
    const Face& face = mesh.faces[i];
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = face.v[k], b = face.v[next(k)], neighbour = face.f[k];
      if (neighbour != kNone && neighbour < i) {
        const Face& other = mesh.faces[neighbour];
        for (int e = 0; e < 3; ++e)
          if (other.v[e] == b && other.v[next(e)] == a) edge_vertex[3 * i + k] = edge_vertex[3 * neighbour + e];
        continue;
      }
      Vertex odd;
      odd.regular = true;
      odd.boundary = neighbour == kNone;
      odd.start_face = 4 * i + 3;
      const glm::dvec3 &pa = mesh.vertices[a].p, &pb = mesh.vertices[b].p;
      if (odd.boundary) {
        odd.p = 0.5 * pa + 0.5 * pb;
      } else {
        const uint32_t opposite = face.v[prev(k)], across = mesh.other_vertex(neighbour, a, b);
        odd.p = 3.0 / 8.0 * pa + 3.0 / 8.0 * pb + 1.0 / 8.0 * mesh.vertices[opposite].p +
                1.0 / 8.0 * mesh.vertices[across].p;
      }
      edge_vertex[3 * i + k] = static_cast<uint32_t>(child.vertices.size());
      child.vertices.push_back(odd);
    }
  }
  return edge_vertex;
}

// One level of Loop subdivision: pbrt-v3's loop body, each face split in four
// (children j at corner j, child 3 in the middle).
Mesh refine(const Mesh& mesh) {
  Mesh child;
  child.vertices.resize(mesh.vertices.size());
  child.faces.resize(4 * mesh.faces.size());
  std::vector<glm::dvec3> ring;
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& vertex = mesh.vertices[i];
    Vertex& even = child.vertices[i];
    even.regular = vertex.regular;
    even.boundary = vertex.boundary;
    if (vertex.boundary) even.p = weight_boundary(mesh, i, 1.0 / 8.0, ring);
    else even.p = weight_one_ring(mesh, i, vertex.regular ? 1.0 / 16.0 : beta(mesh.valence(i)), ring);
    even.start_face = 4 * vertex.start_face + mesh.corner(vertex.start_face, i);
  }
  const std::vector<uint32_t> edge_vertex = add_edge_vertices(mesh, child);
  for (uint32_t i = 0; i < mesh.faces.size(); ++i) {
    const Face& face = mesh.faces[i];
    Face* children = &child.faces[4 * i];
    auto child_at = [&](uint32_t neighbour, uint32_t vertex) {
      return neighbour == kNone ? kNone : 4 * neighbour + mesh.corner(neighbour, vertex);
    };
    for (int j = 0; j < 3; ++j) {
      children[3].f[j] = 4 * i + next(j);
      children[j].f[next(j)] = 4 * i + 3;
      children[j].f[j] = child_at(face.f[j], face.v[j]);
      children[j].f[prev(j)] = child_at(face.f[prev(j)], face.v[j]);
      const uint32_t odd = edge_vertex[3 * i + j];
      children[j].v[j] = face.v[j];
      children[j].v[next(j)] = odd;
      children[next(j)].v[j] = odd;
      children[3].v[j] = odd;
    }
  }
  return child;
}

// pbrt-v3's limit normal, S × T of its tangent masks (not normalised): it
// points against the triangles' winding (S turns towards T the way the ring runs).
glm::dvec3 limit_normal(const Mesh& mesh, uint32_t vertex, std::vector<glm::dvec3>& ring) {
  mesh.one_ring(vertex, ring);
  const int valence = static_cast<int>(ring.size());
  const glm::dvec3 p = mesh.vertices[vertex].p;
  glm::dvec3 s(0.0), t(0.0);
  if (!mesh.vertices[vertex].boundary) {
    for (int j = 0; j < valence; ++j) {
      const double angle = 2 * std::numbers::pi * j / valence;
      s += std::cos(angle) * ring[j];
      t += std::sin(angle) * ring[j];
    }
    return glm::cross(s, t);
  }
  s = ring[valence - 1] - ring[0];
  if (valence == 2) {
    t = ring[0] + ring[1] - 2.0 * p;
  } else if (valence == 3) {
    t = ring[1] - p;
  } else if (valence == 4) {
    t = -ring[0] + 2.0 * ring[1] + 2.0 * ring[2] - ring[3] - 2.0 * p;
  } else {
    const double theta = std::numbers::pi / (valence - 1);
    t = std::sin(theta) * (ring[0] + ring[valence - 1]);
    for (int k = 1; k < valence - 1; ++k) t += (2 * std::cos(theta) - 2) * std::sin(k * theta) * ring[k];
    t = -t;
  }
  return glm::cross(s, t);
}

// The triangle count `levels` make of `faces`, refused past kMaxTriangles or
// past what fits in the memory a render may take. `levels_text` names the
// parameter ("\"integer levels\" 9"), `at` its value.
void check_size(uint64_t faces, int levels, const std::string& levels_text, SourceRange at) {
  uint64_t limit = kMaxTriangles;
  const std::optional<AvailableMemory> available = available_memory();
  const uint64_t bytes_each = loop_subdivision_bytes_per_triangle();
  if (available) limit = std::min(limit, available->bytes / 100 * kUsableMemoryPercent / bytes_each);
  uint64_t triangles = faces;
  for (int level = 0; level < levels && triangles <= limit; ++level) triangles *= 4;
  if (triangles <= limit) return;
  std::string made = levels_text + " of Shape \"loopsubdiv\" makes " + std::to_string(faces) + " × 4^" +
                     std::to_string(levels);
  if (levels < 32 && faces <= std::numeric_limits<uint64_t>::max() >> (2 * levels))
    made += " = " + std::to_string(faces << (2 * levels));
  const std::string help = "each level makes four times the triangles of the one before";
  if (limit == kMaxTriangles)
    fail(at, made + " triangles, more than the " + std::to_string(kMaxTriangles) + " the renderer's 32-bit indices allow",
         help);
  fail(at, made + " triangles, more than the " + std::to_string(limit) + " that fit in " +
               std::to_string(kUsableMemoryPercent) + " % of the " + format_bytes(available->bytes) + " available (" +
               available->source + ") at about " + format_bytes(bytes_each) + " each",
       help);
}

}  // namespace

uint64_t loop_subdivision_bytes_per_triangle() { return kImportBytesPerTriangle + render_bytes_per_triangle(); }

SubdivisionSurface loop_subdivide(std::vector<glm::dvec3> control_points, const std::vector<uint32_t>& indices, int levels,
                                  SourceRange at) {
  Mesh mesh = control_mesh(std::move(control_points), indices, at);
  for (int level = 0; level < levels; ++level) mesh = refine(mesh);
  SubdivisionSurface surface;
  std::vector<glm::dvec3> ring;
  surface.positions.reserve(mesh.vertices.size());
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i)
    surface.positions.push_back(mesh.vertices[i].boundary
                                    ? weight_boundary(mesh, i, 1.0 / 5.0, ring)
                                    : weight_one_ring(mesh, i, loop_gamma(mesh.valence(i)), ring));
  // The tangents are taken on the limit surface: every vertex moved first.
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i].p = surface.positions[i];
  surface.normals.reserve(mesh.vertices.size());
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) surface.normals.push_back(limit_normal(mesh, i, ring));
  surface.indices.reserve(3 * mesh.faces.size());
  for (const Face& face : mesh.faces) surface.indices.insert(surface.indices.end(), face.v.begin(), face.v.end());
  return surface;
}

bool loopsubdiv_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source) {
  if (type != "loopsubdiv") return false;
  // pbrt-v3 reads "levels", else "nlevels", else 3.
  const int levels = params.one_int("levels", params.one_int("nlevels", 3, std::numeric_limits<int>::min(),
                                                             std::numeric_limits<int>::max()),
                                    std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
  const Param* levels_param = params.find("levels", {ParamType::integer});
  if (!levels_param) levels_param = params.find("nlevels", {ParamType::integer});
  if (levels < 0)
    fail(levels_param->values, "\"integer " + levels_param->name + "\" of Shape \"loopsubdiv\" must not be negative",
         "pbrt-v3 would not subdivide at all; 0 is the control mesh moved to its limit surface");
  params.one_string("scheme", "loop");  // pbrt-v3 reads it and subdivides by Loop's rules whatever it says

  const Param* indices = params.find("indices", {ParamType::integer});
  if (!indices) fail(at, "Shape \"loopsubdiv\" needs \"integer indices\" (three per triangle)");
  const Param* p = params.find("P", {ParamType::point3});
  if (!p) fail(at, "Shape \"loopsubdiv\" needs \"point P\" (its control points)");
  if (p->numbers.empty() || p->numbers.size() % 3 != 0)
    fail(p->values, "\"point P\" takes x y z per vertex: " + std::to_string(p->numbers.size()) + " numbers");
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < p->numbers.size(); i += 3) points.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
  if (indices->numbers.empty() || indices->numbers.size() % 3 != 0)
    fail(indices->values, "\"integer indices\" takes three per triangle: " + std::to_string(indices->numbers.size()) +
                              " values");
  std::vector<uint32_t> corners;
  corners.reserve(indices->numbers.size());
  for (double i : indices->numbers) {
    if (i != std::floor(i) || i < 0 || i >= static_cast<double>(points.size()))
      fail(indices->values, "vertex index " + format_number(i) +
                                " is out of range: \"point P\" has " + std::to_string(points.size()) + " vertices");
    corners.push_back(static_cast<uint32_t>(i));
  }
  std::vector<bool> used(points.size(), false);
  for (size_t face = 0; face < corners.size() / 3; ++face) {
    const uint32_t* v = &corners[3 * face];
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
      fail(indices->values, "Shape \"loopsubdiv\": triangle " + std::to_string(face) + " (" + std::to_string(v[0]) + " " +
                                std::to_string(v[1]) + " " + std::to_string(v[2]) + ") repeats a vertex",
           "pbrt-v3 cannot subdivide a triangle of two corners");
    for (int j = 0; j < 3; ++j) used[v[j]] = true;
  }
  for (size_t i = 0; i < used.size(); ++i)
    if (!used[i])
      fail(p->values, "Shape \"loopsubdiv\": vertex " + std::to_string(i) + " of \"point P\" is in no triangle",
           "pbrt-v3 crashes on a vertex no triangle uses; leave it out");
  if (levels_param)
    check_size(corners.size() / 3, levels, "\"integer " + levels_param->name + "\" " + std::to_string(levels),
               levels_param->values);
  else
    check_size(corners.size() / 3, levels, "the default \"levels\" 3", at);

  SubdivisionSurface surface = loop_subdivide(std::move(points), corners, levels, indices->values);
  source.positions = std::move(surface.positions);
  source.normals = std::move(surface.normals);
  source.indices = std::move(surface.indices);
  return true;
}

}  // namespace safegi::render::pbrt
