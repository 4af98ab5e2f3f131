// The pbrt-v3 features of issue 20: pbrt's quadrics as meshes (and NURBS and
// Loop subdivision surfaces), the distant light, integrators substituted by
// name, and materials and textures checked only when a shape uses them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>

#include "pbrt/pbrt_colour.hpp"
#include "pbrt/pbrt_import_test_support.hpp"
#include "pbrt/pbrt_importer.hpp"
#include "safegi/cpu_renderer/memory_estimate.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

// A mesh's area and its area-weighted winding normal (world space, metres).
struct MeshMeasure {
  double area = 0;
  glm::dvec3 normal_sum{0.0};  // Σ area · unit winding normal
  double outward = 0;          // Σ area · (unit normal · radial direction off the z axis)
};
MeshMeasure measure(const Shape& shape) {
  MeshMeasure m;
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
    glm::dvec3 a(sg::raw(shape.positions[shape.indices[i]])), b(sg::raw(shape.positions[shape.indices[i + 1]])),
        c(sg::raw(shape.positions[shape.indices[i + 2]]));
    glm::dvec3 n = glm::cross(b - a, c - a);
    double area = 0.5 * glm::length(n);
    m.area += area;
    m.normal_sum += 0.5 * n;
    glm::dvec3 centre = (a + b + c) / 3.0, radial(centre.x, centre.y, 0);
    if (glm::length(radial) > 0) m.outward += 0.5 * glm::dot(n, glm::normalize(radial));
  }
  return m;
}

// pbrt-v3's quadrics become meshes: each one's area against its closed form
// (256 segments per turn: within 2e-4), with pbrt's (u, v), emitting (as area
// lights) on pbrt's side, its dp/du × dp/dv: the winding normal of an emitter
// (re-wound through the world's mirroring, see Handedness) points there.
TEST(PbrtImport, QuadricsAreMeshesOfTheirArea) {
  const double pi = std::numbers::pi;
  auto shape_of = [](const std::string& text) {
    PbrtScene scene = import(world("AreaLightSource \"diffuse\"\n" + text));
    EXPECT_EQ(scene.scene.shapes.size(), 1u) << text;
    return scene.scene.shapes.at(0);
  };
  Shape disk = shape_of("Shape \"disk\" \"float radius\" 2 \"float innerradius\" 1 \"float height\" 0.5");
  MeshMeasure m = measure(disk);
  EXPECT_NEAR(m.area, pi * (4 - 1), 2e-4 * m.area);
  EXPECT_NEAR(m.normal_sum.z, m.area, 1e-9 * m.area);  // flat, emitting towards +z
  for (const PointObject& p : disk.positions) EXPECT_NEAR(sg::raw(p).z, 0.5f, 1e-6f);
  ASSERT_EQ(disk.uvs.size(), disk.positions.size());
  for (size_t i = 0; i < disk.uvs.size(); ++i)  // pbrt's v: 0 at the rim, 1 at the inner radius
    EXPECT_NEAR(disk.uvs[i].v, (2 - glm::length(glm::vec2(sg::raw(disk.positions[i])))) / (2 - 1), 1e-5f);

  Shape half = shape_of("Shape \"disk\" \"float phimax\" 180");
  EXPECT_NEAR(measure(half).area, pi / 2, 2e-4);

  m = measure(shape_of("Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" -1 \"float zmax\" 2"));
  EXPECT_NEAR(m.area, 2 * pi * 0.5 * 3, 2e-4 * m.area);
  EXPECT_NEAR(m.outward, m.area, 2e-4 * m.area);  // the normals point away from the axis

  m = measure(shape_of("Shape \"cone\" \"float radius\" 1 \"float height\" 2"));
  EXPECT_NEAR(m.area, pi * 1 * std::sqrt(1 + 4), 2e-4 * m.area);
  EXPECT_GT(m.outward, 0);

  // Archimedes: a sphere's zone between two planes has area 2πr·(zmax − zmin).
  m = measure(shape_of("Shape \"sphere\" \"float radius\" 2 \"float zmin\" -0.5 \"float zmax\" 1.5"));
  EXPECT_NEAR(m.area, 2 * pi * 2 * 2, 1e-3 * m.area);
  EXPECT_GT(m.outward, 0);
  m = measure(shape_of("Shape \"sphere\" \"float phimax\" 90"));
  EXPECT_NEAR(m.area, pi, 1e-3 * m.area);
  EXPECT_EQ(shape_of("Shape \"sphere\" \"float zmax\" 5").type, Shape::Type::sphere);  // clamped: whole
  // Scaled unevenly, a sphere is an ellipsoid: a prolate spheroid (a = 1, c = 2) has area
  // 2πa² (1 + c/(a e) asin e), e² = 1 − a²/c².
  Shape spheroid = shape_of("Scale 1 1 2\nShape \"sphere\"");
  EXPECT_EQ(spheroid.type, Shape::Type::mesh);
  const double e = std::sqrt(1 - 1.0 / 4);
  m = measure(spheroid);
  EXPECT_NEAR(m.area, 2 * pi * (1 + 2 / e * std::asin(e)), 1e-3 * m.area);
  EXPECT_GT(m.outward, 0);

  // The paraboloid z = h (r/R)²: area π R/(6h²) ((R² + 4h²)^{3/2} − R³).
  m = measure(shape_of("Shape \"paraboloid\" \"float radius\" 1 \"float zmax\" 2"));
  EXPECT_NEAR(m.area, pi / (6 * 4) * (std::pow(1 + 16, 1.5) - 1), 1e-3 * m.area);
  // A hyperboloid from a line parallel to the axis is a cylinder.
  m = measure(shape_of("Shape \"hyperboloid\" \"point p1\" [1 0 0] \"point p2\" [1 0 3]"));
  EXPECT_NEAR(m.area, 2 * pi * 3, 2e-4 * m.area);
  EXPECT_NEAR(m.outward, m.area, 2e-4 * m.area);

  EXPECT_EQ(import_error(world("ObjectBegin \"o\"\nShape \"sphere\"\nObjectEnd\nScale 1 2 1\nObjectInstance \"o\"")),
            "scene.pbrt:3:7: error: a sphere under an object instance's transform that scales unevenly (an ellipsoid) "
            "is not supported\nShape \"sphere\"\n      ^~~~~~~~\n"
            "help: scale the sphere itself, inside ObjectBegin, and it becomes a mesh\n");
  EXPECT_EQ(import_error(world("Shape \"disk\" \"float innerradius\" 2")),
            "scene.pbrt:2:7: error: \"float innerradius\" of Shape \"disk\" must lie in [0, radius)\n"
            "Shape \"disk\" \"float innerradius\" 2\n      ^~~~~~\n");
}

// pbrt-v3's distant light: irradiance L × scale from the direction from − to,
// mapped as a vector by the transform at the directive.
// pbrt-v3's NURBS become the mesh pbrt-v3 dices them into (30 × 30 vertices): an order-2
// patch is its bilinear quadrilateral, vertex for vertex; a rational quadratic with the
// weight √2/2 on its middle control point is an exact quarter circle, so every vertex of
// that patch extruded along z lies on the unit cylinder.
TEST(PbrtImport, NurbsAreDicedAsPbrtDoes) {
  auto shape_of = [](const std::string& text) {
    PbrtScene scene = import(world(text));
    EXPECT_EQ(scene.scene.shapes.size(), 1u) << text;
    return scene.scene.shapes.at(0);
  };
  const std::string patch = "Shape \"nurbs\" \"integer nu\" 2 \"integer nv\" 2 \"integer uorder\" 2 \"integer vorder\" 2 "
                            "\"float uknots\" [0 0 1 1] \"float vknots\" [0 0 1 1] ";
  Shape square = shape_of("AreaLightSource \"diffuse\"\n" + patch + "\"point P\" [0 0 0  2 0 0  0 1 0  2 1 0]");
  ASSERT_EQ(square.positions.size(), 900u);
  EXPECT_EQ(square.indices.size(), 6u * 29 * 29);
  // (x is mirrored: pbrt-v3's left-handed world becomes ours, see Handedness.)
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) {
      const glm::vec3 p = sg::raw(square.positions[j * 30 + i]);
      EXPECT_NEAR(-p.x, 2.0 * i / 29, 1e-6);
      EXPECT_NEAR(p.y, 1.0 * j / 29, 1e-6);
      EXPECT_EQ(p.z, 0.0f);
      EXPECT_NEAR(square.uvs[j * 30 + i].u, i / 29.0, 1e-6);
    }
  const MeshMeasure flat = measure(square);
  EXPECT_NEAR(flat.area, 2.0, 1e-5);
  EXPECT_NEAR(flat.normal_sum.z, flat.area, 1e-9);  // an emitter on pbrt's side, dp/du × dp/dv = +z

  const std::string w = std::to_string(std::sqrt(0.5));
  Shape arc = shape_of("Shape \"nurbs\" \"integer nu\" 3 \"integer nv\" 2 \"integer uorder\" 3 \"integer vorder\" 2 "
                       "\"float uknots\" [0 0 0 1 1 1] \"float vknots\" [0 0 1 1] \"float Pw\" [1 0 0 1  " + w + " " + w +
                       " 0 " + w + "  0 1 0 1  1 0 1 1  " + w + " " + w + " " + w + " " + w + "  0 1 1 1]");
  for (const PointObject& point : arc.positions) {
    const glm::vec3 p = sg::raw(point);
    EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 2e-6);
    EXPECT_LE(p.x, 1e-6f);  // mirrored
    EXPECT_GE(p.y, -1e-6f);
  }
  // The quarter cylinder's area π/2, as a polygon of 29 chords: within 1e-3.
  EXPECT_NEAR(measure(arc).area, std::numbers::pi / 2, 1e-3);
  // pbrt-v3's vertex normals dp/du × dp/dv: the square's +z (the emitter's side), the arc's the exact
  // cylinder's, radial (the rational derivative included), where the chords' would be off by up to 1.6°.
  ASSERT_EQ(square.normals.size(), 900u);
  for (const normal<Object>& n : square.normals) EXPECT_NEAR(sg::raw(n).z, 1.0f, 1e-6f);
  ASSERT_EQ(arc.normals.size(), arc.positions.size());
  for (size_t i = 0; i < arc.positions.size(); ++i) {
    const glm::vec3 p = sg::raw(arc.positions[i]), n = sg::raw(arc.normals[i]);
    EXPECT_NEAR(std::abs(glm::dot(n, glm::normalize(glm::vec3(p.x, p.y, 0)))), 1.0f, 1e-5f) << i;
  }

  EXPECT_EQ(first_line(import_error(world(patch + "\"point P\" [0 0 0  1 0 0  0 1 0]"))),
            "scene.pbrt:2:143: error: \"point P\" of Shape \"nurbs\" needs nu × nv = 4 points, found 9 numbers");
  EXPECT_EQ(first_line(import_error(world("Shape \"nurbs\" \"integer nu\" 2 \"integer nv\" 2 \"integer uorder\" 2 "
                                          "\"integer vorder\" 2 \"float uknots\" [0 0 1] \"float vknots\" [0 0 1 1]"))),
            "scene.pbrt:2:7: error: Shape \"nurbs\": \"float uknots\" needs nu + uorder = 4 knots, found 3");
  EXPECT_EQ(first_line(import_error(world(patch))),
            "scene.pbrt:2:7: error: Shape \"nurbs\" needs \"point P\" or \"float Pw\" (its control points)");
}

// pbrt-v3's heightfield is its mesh over the unit square: vertex (i, j) at (i/(nu−1), j/(nv−1), Pz),
// those two numbers its texture coordinates, and each cell split along its (i, j)–(i+1, j+1)
// diagonal. With one corner of a single cell raised by 1 that split makes the area
// (1 + √3)/2 ≈ 1.366; the other diagonal would make √2 ≈ 1.414.
TEST(PbrtImport, HeightfieldsAreMeshedAsPbrtDoes) {
  PbrtScene scene = import(world("Shape \"heightfield\" \"integer nu\" 3 \"integer nv\" 2 \"float Pz\" [0 1 2  3 4 5]"));
  ASSERT_EQ(scene.scene.shapes.size(), 1u);
  const Shape& grid = scene.scene.shapes[0];
  ASSERT_EQ(grid.positions.size(), 6u);
  EXPECT_EQ(grid.indices.size(), 3u * 2 * 2);
  EXPECT_TRUE(grid.normals.empty());  // shaded flat, as pbrt-v3 does
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const glm::vec3 p = sg::raw(grid.positions[j * 3 + i]);
      EXPECT_NEAR(-p.x, i / 2.0, 1e-6);  // mirrored: see Handedness
      EXPECT_NEAR(p.y, j, 1e-6);
      EXPECT_EQ(p.z, static_cast<float>(j * 3 + i));
      EXPECT_NEAR(grid.uvs[j * 3 + i].u, i / 2.0, 1e-6);
      EXPECT_NEAR(grid.uvs[j * 3 + i].v, j, 1e-6);
    }
  PbrtScene corner = import(world("Shape \"heightfield\" \"integer nu\" 2 \"integer nv\" 2 \"float Pz\" [0 1 0 0]"));
  EXPECT_NEAR(measure(corner.scene.shapes.at(0)).area, (1 + std::sqrt(3.0)) / 2, 1e-6);

  EXPECT_EQ(first_line(import_error(world("Shape \"heightfield\" \"integer nu\" 2 \"integer nv\" 2 \"float Pz\" [0 1 2]"))),
            "scene.pbrt:2:62: error: \"float Pz\" of Shape \"heightfield\" needs nu × nv = 4 heights, found 3");
  EXPECT_EQ(first_line(import_error(world("Shape \"heightfield\" \"float Pz\" [0]"))),
            "scene.pbrt:2:7: error: Shape \"heightfield\" needs \"integer nu\" and \"integer nv\", each at least 2 (its "
            "grid of heights)");
}

// pbrt-v3's "loopsubdiv" is the mesh its LoopSubdivide makes. The expected
// positions follow from pbrt-v3's rules by hand: an interior vertex of valence
// n moves to (1 − nγ)·p + γ·Σ ring, γ = 1/(n + 3/(8β)), β = 3/16 for n = 3 and
// 3/(8n) above; that is the exact limit (the left eigenvector of Loop's
// vertex mask), so an original vertex's limit is the same at every level.
// A regular tetrahedron's vertex (n = 3, γ = 1/5): 0.4·p + 0.2·(the other
// three) = p/5. A regular octahedron's (n = 4, γ = 1/8): 0.5·p + the ring's
// sum, 0, over 8 = p/2.
const std::string kTetrahedron = "\"point P\" [1 1 1  1 -1 -1  -1 1 -1  -1 -1 1] "
                                 "\"integer indices\" [0 1 2  0 3 1  0 2 3  1 3 2]";  // wound outwards
const std::vector<glm::dvec3> kOctahedron = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const std::vector<uint32_t> kOctahedronFaces = {4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0,
                                                5, 1, 0, 5, 2, 1, 5, 3, 2, 5, 0, 3};  // wound outwards

TEST(PbrtImport, LoopSubdivisionIsPbrtV3s) {
  for (int levels = 0; levels <= 2; ++levels) {
    PbrtScene scene = import(world("Shape \"loopsubdiv\" \"integer levels\" " + std::to_string(levels) + " " + kTetrahedron));
    ASSERT_EQ(scene.scene.shapes.size(), 1u);
    const Shape& mesh = scene.scene.shapes[0];
    const size_t triangles = size_t{4} << (2 * levels);
    EXPECT_EQ(mesh.indices.size(), 3 * triangles) << levels;
    EXPECT_EQ(mesh.positions.size(), std::vector<size_t>({4, 10, 34})[levels]);  // V + E each level
    // The original vertices keep their indices (x mirrored: see Handedness).
    EXPECT_NEAR(glm::distance(sg::raw(mesh.positions[0]), glm::vec3(-0.2f, 0.2f, 0.2f)), 0.0f, 1e-6f) << levels;
    EXPECT_NEAR(glm::distance(sg::raw(mesh.positions[3]), glm::vec3(0.2f, -0.2f, 0.2f)), 0.0f, 1e-6f) << levels;
  }
  // "levels" before "nlevels", 3 without either, as pbrt-v3 reads them.
  EXPECT_EQ(import(world("Shape \"loopsubdiv\" \"integer nlevels\" 2 \"integer levels\" 0 " + kTetrahedron))
                .scene.shapes.at(0).indices.size(), 12u);
  EXPECT_EQ(import(world("Shape \"loopsubdiv\" \"integer nlevels\" 1 " + kTetrahedron)).scene.shapes.at(0).indices.size(),
            3u * 16);
  EXPECT_EQ(import(world("Shape \"loopsubdiv\" " + kTetrahedron)).scene.shapes.at(0).indices.size(), 3u * 256);

  for (int levels = 0; levels <= 2; ++levels) {
    const pbrt::SubdivisionSurface s = pbrt::loop_subdivide(kOctahedron, kOctahedronFaces, levels, {});
    ASSERT_EQ(s.indices.size(), 3 * (size_t{8} << (2 * levels)));
    ASSERT_EQ(s.normals.size(), s.positions.size());
    for (size_t i = 0; i < kOctahedron.size(); ++i)
      EXPECT_NEAR(glm::distance(s.positions[i], 0.5 * kOctahedron[i]), 0.0, 1e-12) << levels << " " << i;
    for (size_t i = 0; i < s.positions.size(); ++i) {
      const glm::dvec3 p = s.positions[i];
      // Inside the control hull |x| + |y| + |z| ≤ 1, and mirrored or turned
      // by the octahedron's symmetries, still a vertex of the mesh.
      EXPECT_LE(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 1.0) << i;
      for (const glm::dvec3 image : {glm::dvec3(-p.x, p.y, p.z), glm::dvec3(p.x, -p.y, p.z), glm::dvec3(p.x, p.y, -p.z),
                                     glm::dvec3(p.y, p.z, p.x)}) {
        double nearest = 1;
        for (const glm::dvec3& q : s.positions) nearest = std::min(nearest, glm::distance(image, q));
        EXPECT_LT(nearest, 1e-12) << levels << " " << i;
      }
      // pbrt-v3's limit normal S × T turns the way its one-ring runs: against
      // the winding, into the solid. At the corner z of the control mesh the
      // ring, walked face to face, is e1, e4, e3, e2 (clockwise seen from
      // outside), on the limit surface at half: S = (e1 − e3)/2, T = (e4 − e2)/2,
      // S × T = −z.
      EXPECT_LT(glm::dot(glm::normalize(s.normals[i]), glm::normalize(p)), -0.5) << levels << " " << i;
    }
    EXPECT_NEAR(glm::distance(s.normals[4] / glm::length(s.normals[4]), glm::dvec3(0, 0, -1)), 0.0, 1e-12);
  }
  EXPECT_NEAR(glm::length(pbrt::loop_subdivide(kOctahedron, kOctahedronFaces, 0, {}).normals[4]), 1.0, 1e-12);

  // An emitter emits on the side of its normals, as pbrt-v3's: inwards here.
  const Shape lamp = import(world("AreaLightSource \"diffuse\"\nShape \"loopsubdiv\" \"integer levels\" 1 " + kTetrahedron))
                         .scene.shapes.at(0);
  for (size_t t = 0; t < lamp.indices.size(); t += 3) {
    const glm::dvec3 a(sg::raw(lamp.positions[lamp.indices[t]])), b(sg::raw(lamp.positions[lamp.indices[t + 1]])),
        c(sg::raw(lamp.positions[lamp.indices[t + 2]]));
    EXPECT_LT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0) << t / 3;
  }
}

// A boundary vertex follows pbrt-v3's boundary rules: subdivided by the cubic
// B-spline's (3/4 itself, 1/8 each boundary neighbour; an edge's midpoint),
// and moved to the limit by pbrt-v3's weights 3/5, 1/5, 1/5 (the B-spline's
// would be 2/3, 1/6, 1/6): a unit square's corner to (0.2, 0.2) from the
// control mesh; after one level the corner is at (1/8, 1/8), its neighbours at
// (1/2, 0) and (0, 1/2), so to (0.175, 0.175); the midpoint (1/2, 0) of an edge
// between (1/8, 1/8) and (7/8, 1/8) to (1/2, 1/20). Normals: −z, against the winding.
TEST(PbrtImport, LoopSubdivisionBoundariesFollowPbrtV3sRules) {
  const std::vector<glm::dvec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<uint32_t> faces = {0, 1, 2, 0, 2, 3};
  pbrt::SubdivisionSurface s = pbrt::loop_subdivide(square, faces, 0, {});
  const std::vector<glm::dvec3> corners = {{0.2, 0.2, 0}, {0.8, 0.2, 0}, {0.8, 0.8, 0}, {0.2, 0.8, 0}};
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(glm::distance(s.positions[i], corners[i]), 0.0, 1e-12) << i;
  s = pbrt::loop_subdivide(square, faces, 1, {});
  ASSERT_EQ(s.positions.size(), 9u);
  ASSERT_EQ(s.indices.size(), 3u * 8);
  EXPECT_NEAR(glm::distance(s.positions[0], glm::dvec3(0.175, 0.175, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(s.positions[2], glm::dvec3(0.825, 0.825, 0)), 0.0, 1e-12);
  // The new vertices in pbrt-v3's order: face 0's edges 0-1, 1-2, 2-0, then face 1's 2-3, 3-0.
  EXPECT_NEAR(glm::distance(s.positions[4], glm::dvec3(0.5, 0.05, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(s.positions[5], glm::dvec3(0.95, 0.5, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(s.positions[6], glm::dvec3(0.5, 0.5, 0)), 0.0, 1e-12);  // inside, symmetric
  for (const glm::dvec3& n : s.normals) {
    EXPECT_EQ(n.x, 0.0);
    EXPECT_EQ(n.y, 0.0);
    EXPECT_LT(n.z, 0.0);
  }
}

// What pbrt-v3's own LoopSubdivide makes of an open fan of seven triangles
// (its centre a boundary vertex of valence 8, where the general boundary
// tangent applies; ends of valence 2 and 3), one level deep: values printed by
// pbrt-v3's loopsubdiv.cpp compiled outside this repository with stand-ins for
// its geometry types (in float; these are ours within 1e-6). The same harness
// gave identical indices, positions within 2e-7 of the mesh's size and
// normals within 0.3° (float rounding) of pbrt-v3's for killeroo.pbrt at
// levels 0, 1 and 3 (docs/pbrt-import.md).
TEST(PbrtImport, LoopSubdivisionAgreesWithPbrtV3sOwnCode) {
  const std::vector<glm::dvec3> fan = {{0, 0, 0.5},   {1, 0, 0},     {1, 1, 0.2},   {0, 1, 0.4},     {-1, 1, 0.2},
                                       {-1, 0, 0},    {-1, -1, -0.2}, {0, -1, -0.4}, {1, -1, -0.2}};
  std::vector<uint32_t> faces;
  for (uint32_t k = 0; k < 7; ++k) faces.insert(faces.end(), {0, 1 + k, 2 + k});
  const pbrt::SubdivisionSurface s = pbrt::loop_subdivide(fan, faces, 1, {});
  ASSERT_EQ(s.positions.size(), 24u);
  ASSERT_EQ(s.indices.size(), 84u);
  EXPECT_EQ(std::vector<uint32_t>(s.indices.begin(), s.indices.begin() + 15),
            std::vector<uint32_t>({0, 9, 11, 9, 1, 10, 11, 10, 2, 9, 10, 11, 0, 11, 13}));
  struct Expected {
    uint32_t vertex;
    glm::dvec3 p, n;
  };
  for (const Expected& e : {Expected{0, {0.35, -0.175, 0.29}, {0.0309520178, 0.0718460083, -0.349493325}},
                            Expected{1, {0.825, 0.175, 0.1225}, {-0.0730000064, 0.0257500131, -0.151249975}},
                            Expected{2, {0.825, 0.825, 0.2}, {-0.0999166742, 0.0122083388, -0.308750063}},
                            Expected{9, {0.525, 0, 0.2375}, {-0.305114627, 0.0807291493, -0.696562648}},
                            Expected{11, {0.510416627, 0.489583343, 0.288541675}, {-0.530652583, 0.0746313557, -2.08346772}}}) {
    EXPECT_NEAR(glm::distance(s.positions[e.vertex], e.p), 0.0, 1e-6) << e.vertex;
    EXPECT_NEAR(glm::distance(s.normals[e.vertex], e.n), 0.0, 1e-6 * glm::length(e.n)) << e.vertex;
  }
}

// SAFEGI_RENDER_MEMORY_LIMIT set for one test, restored after it.
class MemoryLimit {
 public:
  explicit MemoryLimit(const char* limit) {
    if (const char* old = std::getenv("SAFEGI_RENDER_MEMORY_LIMIT")) old_ = old;
    setenv("SAFEGI_RENDER_MEMORY_LIMIT", limit, 1);
  }
  ~MemoryLimit() {
    if (old_) setenv("SAFEGI_RENDER_MEMORY_LIMIT", old_->c_str(), 1);
    else unsetenv("SAFEGI_RENDER_MEMORY_LIMIT");
  }

 private:
  std::optional<std::string> old_;
};

TEST(PbrtImport, LoopSubdivisionErrorsSayWhatPbrtV3CannotSubdivide) {
  auto error = [](const std::string& shape) { return first_line(import_error(world("Shape \"loopsubdiv\" " + shape))); };
  EXPECT_EQ(error("\"point P\" [0 0 0  1 0 0  0 1 0]"),
            "scene.pbrt:2:7: error: Shape \"loopsubdiv\" needs \"integer indices\" (three per triangle)");
  EXPECT_EQ(error("\"integer indices\" [0 1 2]"),
            "scene.pbrt:2:7: error: Shape \"loopsubdiv\" needs \"point P\" (its control points)");
  EXPECT_EQ(error("\"integer indices\" [0 1 2] \"point P\" [0 0 0  1 0 0  0 1]"),
            "scene.pbrt:2:56: error: \"point P\" takes x y z per vertex: 8 numbers");
  EXPECT_EQ(error("\"integer indices\" [0 1] \"point P\" [0 0 0  1 0 0  0 1 0]"),
            "scene.pbrt:2:38: error: \"integer indices\" takes three per triangle: 2 values");
  EXPECT_EQ(error("\"integer indices\" [0 1 3] \"point P\" [0 0 0  1 0 0  0 1 0]"),
            "scene.pbrt:2:38: error: vertex index 3 is out of range: \"point P\" has 3 vertices");
  EXPECT_EQ(error("\"integer indices\" [0 1 1] \"point P\" [0 0 0  1 0 0  0 1 0]"),
            "scene.pbrt:2:38: error: Shape \"loopsubdiv\": triangle 0 (0 1 1) repeats a vertex");
  EXPECT_EQ(error("\"integer indices\" [0 1 2] \"point P\" [0 0 0  1 0 0  0 1 0  1 1 1]"),
            "scene.pbrt:2:56: error: Shape \"loopsubdiv\": vertex 3 of \"point P\" is in no triangle");
  EXPECT_EQ(import_error(world("Shape \"loopsubdiv\" \"integer indices\" [0 1 2  1 0 3  0 1 4] "
                               "\"point P\" [0 0 0  1 0 0  0 1 0  0 -1 0  0 0 1]")),
            "scene.pbrt:2:38: error: Shape \"loopsubdiv\": the edge between vertices 0 and 1 belongs to 3 triangles "
            "(0, 1 and 2)\nShape \"loopsubdiv\" \"integer indices\" [0 1 2  1 0 3  0 1 4] \"point P\" [0 0 0  1 0 0  0 1 0  "
            "0 -1 0  0 0 1]\n                                     ^~~~~~~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 subdivides only meshes whose every edge belongs to one or two triangles\n");
  EXPECT_EQ(error("\"integer indices\" [0 1 2  0 1 3] \"point P\" [0 0 0  1 0 0  0 1 0  0 -1 0]"),
            "scene.pbrt:2:38: error: Shape \"loopsubdiv\": triangles 0 and 1 both run from vertex 0 to vertex 1");
  EXPECT_EQ(error("\"integer levels\" -1 " + kTetrahedron),
            "scene.pbrt:2:37: error: \"integer levels\" of Shape \"loopsubdiv\" must not be negative");
  {
    MemoryLimit plenty("1TiB");  // the renderer's 32-bit indices decide
    EXPECT_EQ(error("\"integer nlevels\" 15 " + kTetrahedron),
              "scene.pbrt:2:38: error: \"integer nlevels\" 15 of Shape \"loopsubdiv\" makes 4 × 4^15 = 4294967296 "
              "triangles, more than the 2147483648 the renderer's 32-bit indices allow");
    EXPECT_EQ(error("\"integer levels\" 2000000000 " + kTetrahedron),
              "scene.pbrt:2:37: error: \"integer levels\" 2000000000 of Shape \"loopsubdiv\" makes 4 × 4^2000000000 "
              "triangles, more than the 2147483648 the renderer's 32-bit indices allow");
  }
  MemoryLimit small("1MiB");
  const uint64_t each = pbrt::loop_subdivision_bytes_per_triangle();
  EXPECT_EQ(error("\"integer levels\" 6 " + kTetrahedron),
            "scene.pbrt:2:37: error: \"integer levels\" 6 of Shape \"loopsubdiv\" makes 4 × 4^6 = 16384 triangles, "
            "more than the " + std::to_string(1048576 / 100 * 80 / each) + " that fit in 80 % of the 1.0 MiB available "
            "(SAFEGI_RENDER_MEMORY_LIMIT) at about " + format_bytes(each) + " each");
  EXPECT_EQ(import(world("Shape \"loopsubdiv\" \"integer levels\" 2 " + kTetrahedron)).scene.shapes.size(), 1u);
}

// Blender's exporter writes meshes of nothing; pbrt-v3 makes no shape of one
// and goes on: so do we, with a warning, even under an area light.
TEST(PbrtImport, AnEmptyTriangleMeshMakesNothing) {
  PbrtScene scene = import(world("AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                 "Shape \"trianglemesh\" \"point P\" [ ] \"integer indices\" [ ] \"normal N\" [ ] \"float uv\" [ ]\n"
                                 "Shape \"trianglemesh\" \"point P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [ ]\n"
                                 "Shape \"sphere\""));
  ASSERT_EQ(scene.scene.shapes.size(), 1u);  // the sphere alone
  EXPECT_EQ(scene.scene.shapes[0].type, Shape::Type::sphere);
  EXPECT_EQ(scene.warnings.find("not used"), std::string::npos) << scene.warnings;
  EXPECT_NE(scene.warnings.find("scene.pbrt:3:7: warning: an empty triangle mesh (no \"point P\") makes nothing"),
            std::string::npos)
      << scene.warnings;
  EXPECT_NE(scene.warnings.find("scene.pbrt:4:7: warning: an empty triangle mesh (no \"integer indices\") makes nothing"),
            std::string::npos)
      << scene.warnings;
  // A mesh with vertices but its indices left out is still an error (pbrt-v3's too).
  EXPECT_EQ(first_line(import_error(world("Shape \"trianglemesh\" \"point P\" [0 0 0  1 0 0  0 1 0  1 1 0]"))),
            "scene.pbrt:2:1: error: Shape \"trianglemesh\" needs \"integer indices\" (three per triangle)");
}

// ActiveTransform: a shape's transform at pbrt-v3's two TransformTimes becomes its poses at
// shutter open and close (the camera's shutter is those times), which the renderer
// interpolates as pbrt-v3's AnimatedTransform does. Every point is where pbrt-v3 puts it
// at both times, through the mirroring of pbrt-v3's left-handed world in ours.
TEST(PbrtImport, AnimatedTransformsMoveShapesBetweenShutterOpenAndClose) {
  PbrtScene scene = import("TransformTimes 0 1\nCamera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 1\n" +
                           world("AttributeBegin\nTranslate 0 0 5\nActiveTransform EndTime\nTranslate 2 0 0\nRotate 90 0 0 1\n"
                                 "ActiveTransform All\nScale 2 2 2\n"
                                 "Shape \"trianglemesh\" \"point P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n"
                                 "Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n"
                                 "Shape \"sphere\" \"float radius\" 1"));
  ASSERT_EQ(scene.scene.shapes.size(), 3u);
  EXPECT_EQ(sg::raw(scene.scene.camera.shutter_open), 0.0f);
  EXPECT_EQ(sg::raw(scene.scene.camera.shutter_close), 1.0f);
  const Shape& mesh = scene.scene.shapes[0];
  ASSERT_TRUE(mesh.render_from_object_at_close.has_value());
  // pbrt's object point (1, 0, 0): at the start (2, 0, 5); at the end rotated to (0, 2) and
  // moved by 2 along x: (2, 2, 5). Ours mirror x.
  const glm::vec3 open = sg::raw(mesh.render_from_object(mesh.positions[1]));
  const glm::vec3 close = sg::raw((*mesh.render_from_object_at_close)(mesh.positions[1]));
  EXPECT_NEAR(glm::distance(open, glm::vec3(-2, 0, 5)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(close, glm::vec3(-2, 2, 5)), 0.0f, 1e-5f);
  // Each pose is a rotation and a uniform scale (no mirroring left in it): what RigidMotion slerps.
  const glm::mat3 linear(sg::raw(mesh.render_from_object).forward);
  EXPECT_GT(glm::determinant(linear), 0.0f);
  const Shape& sphere = scene.scene.shapes[1];
  ASSERT_TRUE(sphere.render_from_object_at_close.has_value());
  EXPECT_NEAR(glm::distance(sg::raw((*sphere.render_from_object_at_close)(sphere.center)), glm::vec3(-2, 0, 5)), 0.0f, 1e-5f);
  EXPECT_NEAR(sg::raw(placed_radius(sphere.render_from_object, sphere.radius)), 1.0f, 1e-6f);
  EXPECT_FALSE(scene.scene.shapes[2].render_from_object_at_close.has_value());  // after AttributeEnd: static

  // An emitter that moves does not emit (pbrt-v3 drops its area light too), with a warning.
  PbrtScene light = import(world("ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\n"
                                 "AreaLightSource \"diffuse\"\nShape \"sphere\""));
  EXPECT_FALSE(light.scene.shapes.at(0).emission.has_value());
  EXPECT_NE(light.warnings.find("an animated shape does not emit"), std::string::npos) << light.warnings;
  // The shutter must be the TransformTimes.
  EXPECT_NE(import_error("TransformTimes 0 2\n" + world("ActiveTransform EndTime\nTranslate 1 0 0\nShape \"sphere\""))
                .find("is not supported\nShape \"sphere\""),
            std::string::npos);
}

TEST(PbrtImport, DistantLightArrivesFromFromMinusTo) {
  PbrtScene scene = import(world("Rotate 90 1 0 0\nLightSource \"distant\" \"point from\" [0 0 0] \"point to\" [0 0 -2] "
                                 "\"rgb L\" [2 1 0.5] \"rgb scale\" [1.5 1.5 1.5]"));
  ASSERT_EQ(scene.scene.distant_lights.size(), 1u);
  const DistantLight& sun = scene.scene.distant_lights[0];
  // +z (from − to) turned 90° about x is −y; the world's mirroring across x leaves it.
  EXPECT_NEAR(sg::raw(sun.direction).x, 0, 1e-6f);
  EXPECT_NEAR(sg::raw(sun.direction).y, -1, 1e-6f);
  EXPECT_NEAR(sg::raw(sun.direction).z, 0, 1e-6f);
  EXPECT_EQ(sg::raw(sun.irradiance), glm::vec3(3, 1.5f, 0.75f));
  EXPECT_EQ(import_error(world("LightSource \"distant\" \"point from\" [1 1 1] \"point to\" [1 1 1]")),
            "scene.pbrt:2:1: error: the distant light's \"from\" and \"to\" coincide\n"
            "LightSource \"distant\" \"point from\" [1 1 1] \"point to\" [1 1 1]\n^~~~~~~~~~~\n");
}

// Kim et al.'s cubic fit of the Planckian locus (2002, 1667-25000 K): the
// chromaticity of a blackbody, independent of our integration.
std::array<double, 2> planckian_locus(double t) {
  double x = t <= 4000 ? -0.2661239e9 / (t * t * t) - 0.2343589e6 / (t * t) + 0.8776956e3 / t + 0.179910
                       : -3.0258469e9 / (t * t * t) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
  double y = t <= 2222   ? -1.1063814 * x * x * x - 1.34811020 * x * x + 2.18555832 * x - 0.20219683
             : t <= 4000 ? -0.9549476 * x * x * x - 1.37418593 * x * x + 2.09137015 * x - 0.16748867
                         : 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
  return {x, y};
}

// pbrt-v3's "blackbody" [temperature scale]: its chromaticity is on the
// Planckian locus (within 1.5e-3 from 2700 K up, 4e-3 at 2000 K: Wyman et
// al.'s fit of the colour-matching functions errs most in the red tail, where
// a cool blackbody's energy is; measured 2.6e-3 / 2.9e-3 in y / x at 2000 K),
// its luminance is that of Planck's law normalised at its peak (a 6500 K
// spectrum peaks at 446 nm, inside the visible range, so Y is near 0.88), and
// the scale multiplies it.
TEST(PbrtImport, BlackbodyColoursFollowThePlanckianLocus) {
  for (double kelvin : {2000.0, 2700.0, 4000.0, 6500.0, 10000.0, 20000.0}) {
    std::array<double, 3> xyz = pbrt::normalized_blackbody_xyz(kelvin);
    double sum = xyz[0] + xyz[1] + xyz[2];
    std::array<double, 2> locus = planckian_locus(kelvin);
    double tolerance = kelvin < 2500 ? 4e-3 : 1.5e-3;
    EXPECT_NEAR(xyz[0] / sum, locus[0], tolerance) << kelvin;
    EXPECT_NEAR(xyz[1] / sum, locus[1], tolerance) << kelvin;
  }
  EXPECT_NEAR(pbrt::normalized_blackbody_xyz(6500)[1], 0.884, 0.01);
  std::array<double, 3> warm = pbrt::normalized_blackbody_rgb(2700), cool = pbrt::normalized_blackbody_rgb(10000);
  EXPECT_GT(warm[0], warm[1]);
  EXPECT_GT(warm[1], warm[2]);
  EXPECT_GT(cool[2], cool[1]);
  EXPECT_GT(cool[1], cool[0]);

  PbrtScene scene = import(world("LightSource \"point\" \"blackbody I\" [2700 3]"));
  ASSERT_EQ(scene.scene.point_lights.size(), 1u);
  glm::vec3 intensity = sg::raw(scene.scene.point_lights[0].intensity);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(intensity[k], 3 * warm[k], 1e-5) << k;
  EXPECT_EQ(import_error(world("LightSource \"point\" \"blackbody I\" [2700]")),
            "scene.pbrt:2:35: error: \"blackbody I\" takes [temperature scale] (2 values, pbrt-v3), found 1\n"
            "LightSource \"point\" \"blackbody I\" [2700]\n                                  ^~~~~~\n");
}

// pbrt-v3's metal (src/materials/metal.cpp): η and k by spectrum, copper's by
// default, roughness 0.01 remapped. The expected RGB values are pbrt-v3's own,
// computed outside this test with its RGBSpectrum::FromSampled and its 471-entry
// CIE table (the same samples and scale, in double precision); ours integrate
// Wyman et al.'s fit of the CIE functions instead (pbrt_colour.cpp), which
// puts η and k within 2 % of pbrt-v3's (measured: 1.8 % at worst, gold's and
// copper's red η) and the normal-incidence reflectance ((η−1)² + k²) /
// ((η+1)² + k²) within 3e-3 (measured 2.7e-3, copper's green).
TEST(PbrtImport, MetalAsPbrtV3DefinesIt) {
  struct Expected {
    const char* directive;
    std::array<double, 3> eta, k;
  };
  const Expected pbrt_v3[] = {
      {"Material \"metal\"", {0.19999, 0.92209, 1.09988}, {3.90464, 2.44763, 2.13765}},  // CopperN, CopperK
      {"Material \"metal\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"",
       {0.14282, 0.37414, 1.43944}, {3.97472, 2.38066, 1.59981}},
      {"Material \"metal\" \"spectrum eta\" \"metal-Ag-eta\" \"spectrum k\" \"metal-Ag-k\"",
       {0.15494, 0.11648, 0.13809}, {4.81810, 3.11562, 2.14240}},
      {"Material \"metal\" \"spectrum eta\" \"metal-Al-eta\" \"spectrum k\" \"metal-Al-k\"",
       {1.65394, 0.87850, 0.52012}, {9.20430, 6.25621, 4.82675}},
      {"Material \"metal\" \"spectrum eta\" \"metal-CuZn-eta\" \"spectrum k\" \"metal-CuZn-k\"",
       {0.51867, 0.48747, 1.03980}, {4.32139, 2.54270, 1.58851}},
  };
  auto normal_reflectance = [](double eta, double k) {
    return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
  };
  for (const Expected& expected : pbrt_v3) {
    PbrtScene scene = import(world(used(expected.directive)));
    ASSERT_EQ(scene.scene.shapes.size(), 1u) << expected.directive;
    ConductorMaterial metal = as<ConductorMaterial>(scene.scene.materials.at(scene.scene.shapes[0].material));
    EXPECT_NEAR(metal.alpha, pbrt_alpha(0.01), 1e-6) << expected.directive;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(metal.eta[c], expected.eta[c], 0.02 * expected.eta[c]) << expected.directive << ", channel " << c;
      EXPECT_NEAR(metal.k[c], expected.k[c], 0.02 * expected.k[c]) << expected.directive << ", channel " << c;
      EXPECT_NEAR(normal_reflectance(metal.eta[c], metal.k[c]), normal_reflectance(expected.eta[c], expected.k[c]), 3e-3)
          << expected.directive << ", channel " << c;
    }
    EXPECT_EQ(scene.warnings, "") << expected.directive;
  }

  PbrtScene scene = import(world(
      "Material \"metal\" \"rgb eta\" [0.2 0.9 1.1] \"rgb k\" [3.9 2.4 2.1] \"float roughness\" 0.3 "
      "\"bool remaproughness\" \"false\"\nShape \"sphere\"\n"                                     // 0: as given
      "Material \"metal\" \"float uroughness\" 0.2 \"float vroughness\" 0.2\nShape \"sphere\"\n"  // 1: isotropic
      "Material \"metal\" \"float roughness\" 0 \"bool remaproughness\" \"false\"\nShape \"sphere\"\n"  // 2: floor
      // 3: sampled pairs, in any order; a constant spectrum is the grey of pbrt-v3's white (1.2, 0.95, 0.91 for 1)
      "Material \"metal\" \"spectrum eta\" [700 1.5 400 1.5] \"spectrum k\" [550 2]\nShape \"sphere\"\n"
      "Texture \"one\" \"spectrum\" \"constant\" \"rgb value\" [1 1 1]\n"  // 4: a constant texture is a constant
      "Material \"metal\" \"texture k\" \"one\"\nShape \"sphere\""));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 5u);
  auto metal = [&](size_t shape) { return as<ConductorMaterial>(s.materials.at(s.shapes[shape].material)); };
  EXPECT_EQ(sg::raw(metal(0).eta), glm::vec3(0.2f, 0.9f, 1.1f));
  EXPECT_EQ(sg::raw(metal(0).k), glm::vec3(3.9f, 2.4f, 2.1f));
  EXPECT_EQ(metal(0).alpha, 0.3f);
  EXPECT_NEAR(metal(1).alpha, pbrt_alpha(0.2), 1e-6);
  EXPECT_EQ(metal(2).alpha, 0.001f);  // TrowbridgeReitzDistribution's floor
  std::array<double, 3> white = pbrt::sampled_spectrum_rgb({{550, 1}});
  EXPECT_NEAR(white[0], 1.2, 0.01);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(metal(3).eta[c], 1.5 * white[c], 1e-6) << c;
    EXPECT_NEAR(metal(3).k[c], 2 * white[c], 1e-6) << c;
  }
  EXPECT_EQ(sg::raw(metal(4).k), glm::vec3(1));

  // What the renderer cannot represent, and values the Fresnel equations cannot take.
  auto error_of = [](const std::string& material) { return first_line(import_error(world(used(material)))); };
  EXPECT_EQ(error_of("Material \"metal\" \"float uroughness\" 0.2"),
            "scene.pbrt:2:10: error: an anisotropic Material \"metal\" (\"uroughness\" 0.2, \"vroughness\" 0.01) is not "
            "supported");
  EXPECT_EQ(import_error(world(used("Material \"metal\" \"spectrum eta\" \"spds/Cu.eta.spd\""))),
            "scene.pbrt:2:33: error: cannot read spectrum file 'dir/spds/Cu.eta.spd': no such file\n"
            "Material \"metal\" \"spectrum eta\" \"spds/Cu.eta.spd\"\n"
            "                                ^~~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 resolves it against the directory of the main scene file (and renders black without it); "
            "named spectra: \"metal-Ag-eta\", \"metal-Ag-k\", \"metal-Al-eta\", \"metal-Al-k\", \"metal-Au-eta\", "
            "\"metal-Au-k\", \"metal-Cu-eta\", \"metal-Cu-k\", \"metal-CuZn-eta\", \"metal-CuZn-k\"\n");
  EXPECT_EQ(import_error(world(used("Material \"metal\" \"rgb eta\" [0 1 1]"))),
            "scene.pbrt:2:18: error: \"eta\" of Material \"metal\" must lie in (0, 1000] in every channel, found "
            "[0 1 1]\nMaterial \"metal\" \"rgb eta\" [0 1 1]\n                 ^~~~~~~~~\n"
            "help: eta is the real part of the metal's index over the outside's: copper's is 0.2 to 1.1\n");
  EXPECT_EQ(error_of("Material \"metal\" \"rgb k\" [1 -1 1]"),
            "scene.pbrt:2:18: error: \"k\" of Material \"metal\" must lie in [0, 1000] in every channel, found [1 -1 1]");
  EXPECT_EQ(error_of("Material \"metal\" \"spectrum k\" [400 1 500]"),
            "scene.pbrt:2:31: error: \"spectrum k\" takes [wavelength value ...] pairs, found 3 numbers");
  EXPECT_EQ(error_of("Material \"metal\" \"spectrum k\" [400 1 400 2]"),
            "scene.pbrt:2:31: error: \"spectrum k\" gives the wavelength 400 nm twice");
  EXPECT_EQ(error_of("Material \"metal\" \"float eta\" 1.5"),
            "scene.pbrt:2:18: error: Material \"metal\" reads \"eta\" as \"rgb\", \"xyz\", \"blackbody\", \"spectrum\" or "
            "\"texture\", found \"float eta\"");
  EXPECT_EQ(error_of("Material \"metal\" \"float roughness\" 1e39 \"bool remaproughness\" \"false\""),
            "scene.pbrt:2:10: error: the roughness of Material \"metal\" is out of float range");
  EXPECT_EQ(import_error(world("Texture \"t\" \"spectrum\" \"checkerboard\"\n" +
                               used("Material \"metal\" \"texture eta\" \"t\""))),
            "scene.pbrt:3:18: error: a procedural texture as \"eta\" of Material \"metal\" is not supported\n"
            "Material \"metal\" \"texture eta\" \"t\"\n                 ^~~~~~~~~~~~~\n"
            "help: a metal's \"eta\" and \"k\" are constants here: rgb, a named spectrum or [wavelength value ...] pairs\n");
  EXPECT_EQ(first_line(import_error(world("Texture \"r\" \"float\" \"fbm\"\n" +
                                          used("Material \"metal\" \"texture roughness\" \"r\"")))),
            "scene.pbrt:3:18: error: a procedural texture as \"roughness\" of Material \"metal\" is not supported");
  EXPECT_EQ(error_of("Material \"metal\" \"texture bumpmap\" \"b\""),
            "scene.pbrt:2:36: error: no float texture named \"b\"");
}

// pbrt-v3's substrate (src/materials/substrate.cpp): "Kd" and "Ks" 0.5,
// "uroughness" and "vroughness" 0.1 each (no "roughness"), remapped by
// default; "Kd" textured as matte's; black when both reflectances are.
TEST(PbrtImport, SubstrateAsPbrtV3DefinesIt) {
  PbrtScene scene = import(world(
      "Material \"substrate\"\nShape \"sphere\"\n"  // 0: pbrt-v3's defaults
      // 1: as given; Kd + Ks above 1 is no warning (FresnelBlend weights Kd by 1 - Ks)
      "Material \"substrate\" \"rgb Kd\" [0.2 0.3 0.4] \"rgb Ks\" [0.9 0.8 0.7] \"float uroughness\" 0.3 "
      "\"float vroughness\" 0.3 \"bool remaproughness\" \"false\"\nShape \"sphere\"\n"
      "Material \"substrate\" \"float uroughness\" 0.2 \"float vroughness\" 0.2\nShape \"sphere\"\n"  // 2: remapped
      "Material \"substrate\" \"float uroughness\" 0 \"float vroughness\" 0 \"bool remaproughness\" \"false\"\n"
      "Shape \"sphere\"\n"  // 3: TrowbridgeReitzDistribution's floor
      // 4: a textured Kd; a black Ks still leaves FresnelBlend (its Schlick term is not 0 at grazing angles)
      "Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"substrate\" \"texture Kd\" \"t\" \"rgb Ks\" [0 0 0]\n"
      "Shape \"sphere\"\n"
      "Material \"substrate\" \"rgb Kd\" [0 0 0] \"rgb Ks\" [0 0 0]\nShape \"sphere\""));  // 5: no BxDF: black
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 6u);
  auto substrate = [&](size_t shape) { return as<SubstrateMaterial>(s.materials.at(s.shapes[shape].material)); };
  EXPECT_EQ(sg::raw(substrate(0).diffuse.value), glm::vec3(0.5f));
  EXPECT_FALSE(substrate(0).diffuse.textured());
  EXPECT_EQ(sg::raw(substrate(0).specular), glm::vec3(0.5f));
  EXPECT_NEAR(substrate(0).alpha, pbrt_alpha(0.1), 1e-6);
  EXPECT_EQ(sg::raw(substrate(1).diffuse.value), glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_EQ(sg::raw(substrate(1).specular), glm::vec3(0.9f, 0.8f, 0.7f));
  EXPECT_EQ(substrate(1).alpha, 0.3f);
  EXPECT_NEAR(substrate(2).alpha, pbrt_alpha(0.2), 1e-6);
  EXPECT_EQ(substrate(3).alpha, 0.001f);
  EXPECT_EQ(substrate(4).diffuse.pattern, 0);
  EXPECT_EQ(sg::raw(substrate(4).specular), glm::vec3(0));
  EXPECT_EQ(diffuse(s.materials.at(s.shapes[4].material)).pattern, 0);  // what the integrator's textures look up
  EXPECT_EQ(s.shapes[5].material, -1);
  EXPECT_EQ(scene.warnings, "");

  EXPECT_EQ(import_error(world(used("Material \"substrate\" \"float uroughness\" 0.2"))),
            "scene.pbrt:2:10: error: an anisotropic Material \"substrate\" (\"uroughness\" 0.2, \"vroughness\" 0.1) is "
            "not supported\nMaterial \"substrate\" \"float uroughness\" 0.2\n         ^~~~~~~~~~~\n"
            "help: the microfacet lobe here is isotropic: give \"uroughness\" and \"vroughness\" one value\n");
  auto error_of = [](const std::string& material) { return first_line(import_error(world(used(material)))); };
  EXPECT_EQ(error_of("Material \"substrate\" \"rgb Ks\" [1.2 0.5 0.5]"),
            "scene.pbrt:2:22: error: \"Ks\" of Material \"substrate\" must lie in [0, 1] in every channel");
  EXPECT_EQ(error_of("Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"substrate\" \"texture Ks\" \"t\""),
            "scene.pbrt:3:22: error: a procedural texture as \"Ks\" of Material \"substrate\" is not supported");
  // pbrt-v3's substrate reads no "roughness": the parameter is reported unused, as pbrt-v3 ignores it.
  PbrtScene rough = import(world(used("Material \"substrate\" \"float roughness\" 0.5")));
  EXPECT_NEAR(as<SubstrateMaterial>(rough.scene.materials.at(rough.scene.shapes[0].material)).alpha, pbrt_alpha(0.1), 1e-6);
  EXPECT_NE(rough.warnings.find("parameter \"float roughness\" of Material \"substrate\" is not used"), std::string::npos)
      << rough.warnings;
}

// pbrt-v3's spectrum files (.spd, as pbrt-v3-scenes ship them for metals):
// [wavelength value ...] pairs with '#' comments, resolved against the main
// file's directory, read as its ReadFloatFile reads them, then converted as
// pairs written in the scene are.
TEST(PbrtImport, SpectrumFilesAreReadAsPbrtV3ReadsThem) {
  PbrtImportOptions files = in_memory({{"dir/spds/test.eta.spd", "# a test metal\n400 1.5\t500 1.0\n# more\n600 +0.3e0\n"},
                                       {"dir/spds/odd.spd", "400 1 500"},
                                       {"dir/spds/words.spd", "400 1\n500 one\n"}});
  PbrtScene scene = import(world(used("Material \"metal\" \"spectrum eta\" \"spds/test.eta.spd\"")), files);
  ASSERT_EQ(scene.scene.shapes.size(), 1u);
  ConductorMaterial metal = as<ConductorMaterial>(scene.scene.materials.at(scene.scene.shapes[0].material));
  std::array<double, 3> expected = pbrt::sampled_spectrum_rgb({{400, 1.5}, {500, 1.0}, {600, 0.3}});
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(metal.eta[c], static_cast<float>(expected[c])) << c;
  EXPECT_EQ(first_line(import_error(world(used("Material \"metal\" \"spectrum eta\" \"spds/odd.spd\"")), files)),
            "scene.pbrt:2:33: error: spectrum file 'dir/spds/odd.spd' holds 3 numbers, not [wavelength value ...] pairs");
  EXPECT_EQ(first_line(import_error(world(used("Material \"metal\" \"spectrum eta\" \"spds/words.spd\"")), files)),
            "scene.pbrt:2:33: error: spectrum file 'dir/spds/words.spd', line 2: 'o' is neither a number nor a '#' "
            "comment");
}

// pbrt-v3's path, directlighting and whitted stop shadow rays at every
// surface, one of material "none" too; volpath, bdpt and mlt let them through.
TEST(PbrtImport, SurfacesWithoutMaterialOccludeLightWhereThePbrtV3IntegratorSaysSo) {
  const std::string emitter = "AreaLightSource \"diffuse\" \"bool twosided\" \"true\"\nMaterial \"none\"\nShape \"sphere\"";
  for (const char* integrator : {"path", "directlighting", "whitted"}) {
    PbrtScene scene = import("Integrator \"" + std::string(integrator) + "\"\n" + world(emitter));
    ASSERT_EQ(scene.scene.shapes.size(), 1u);
    EXPECT_TRUE(scene.scene.shapes[0].invisible);
    EXPECT_TRUE(scene.scene.shapes[0].occludes_light) << integrator;
  }
  for (const char* integrator : {"volpath", "bdpt", "mlt"}) {
    PbrtScene scene = import("Integrator \"" + std::string(integrator) + "\"\n" + world(emitter));
    ASSERT_EQ(scene.scene.shapes.size(), 1u);
    EXPECT_FALSE(scene.scene.shapes[0].occludes_light) << integrator;
  }
  EXPECT_FALSE(import(world(used("Material \"matte\""))).scene.shapes[0].occludes_light);  // visible: blocks as any surface
}

// pbrt-v3's SPPM is ours (integrator sppm): "iterations" (older:
// "numiterations", default 64) passes of "photonsperiteration" photons
// (default -1: the film's pixels, counted when rendering), from visible points
// of initial "radius" (default 1, in scene units), read without a warning.
TEST(PbrtImport, SppmReadsItsParameters) {
  PbrtScene given = import("Integrator \"sppm\" \"integer iterations\" 10 \"integer photonsperiteration\" 5000 "
                           "\"float radius\" 0.25 \"integer maxdepth\" 7 \"integer imagewritefrequency\" 3\n" + world(""));
  EXPECT_EQ(given.scene.settings.integrator, IntegratorType::sppm);
  EXPECT_EQ(given.scene.settings.sppm_iterations, 10);
  EXPECT_EQ(given.scene.settings.sppm_photons_per_iteration, 5000);
  EXPECT_FLOAT_EQ(sg::raw(given.scene.settings.sppm_radius), 0.25f);  // metres: one scene unit is a metre here
  EXPECT_EQ(given.scene.settings.max_depth, 7);
  EXPECT_EQ(given.warnings, "");
  // "iterations" wins over "numiterations", as in pbrt-v3; "numiterations" alone counts.
  EXPECT_EQ(import("Integrator \"sppm\" \"integer numiterations\" 3 \"integer iterations\" 7\n" + world(""))
                .scene.settings.sppm_iterations,
            7);
  EXPECT_EQ(import("Integrator \"sppm\" \"integer numiterations\" 3\n" + world("")).scene.settings.sppm_iterations, 3);
  // Defaults: 64 iterations of one photon per pixel (-1), radius 1, depth 5.
  PbrtScene plain = import("Integrator \"sppm\"\n" + world(""));
  EXPECT_EQ(plain.scene.settings.sppm_iterations, 64);
  EXPECT_EQ(plain.scene.settings.sppm_photons_per_iteration, -1);
  EXPECT_FLOAT_EQ(sg::raw(plain.scene.settings.sppm_radius), 1.0f);
  EXPECT_EQ(plain.scene.settings.max_depth, 5);
  EXPECT_EQ(plain.warnings, "");
}

// pbrt-v3's integrators we do not have render with the nearest we do, and a
// warning names the substitution; their own parameters are read (noise only).
// bdpt is ours too, where it can render the scene.
TEST(PbrtImport, MissingIntegratorsAreSubstitutedByName) {
  PbrtScene bdpt = import("Integrator \"bdpt\" \"integer maxdepth\" 7 \"bool visualizestrategies\" \"false\"\n" + world(""));
  EXPECT_EQ(bdpt.scene.settings.integrator, IntegratorType::bdpt);
  EXPECT_EQ(bdpt.scene.settings.max_depth, 7);
  EXPECT_EQ(bdpt.warnings, "");
  // A scene ours cannot render bidirectionally (here: an environment light): the path tracer, and why.
  PbrtScene sky = import("Integrator \"bdpt\" \"integer maxdepth\" 7\n" + world("LightSource \"infinite\""));
  EXPECT_EQ(sky.scene.settings.integrator, IntegratorType::path);
  EXPECT_EQ(sky.scene.settings.max_depth, 7);
  EXPECT_EQ(sky.warnings,
            "scene.pbrt:1:12: warning: integrator \"bdpt\": bdpt cannot render this scene (the scene has an environment "
            "light): rendering with \"path\"\n"
            "Integrator \"bdpt\" \"integer maxdepth\" 7\n           ^~~~~~\n"
            "help: the same image in expectation except caustics of point and spot lights seen through specular "
            "surfaces, which the path tracer cannot sample\n");
  // sppm is ours: no substitution.
  PbrtScene sppm = import("Integrator \"sppm\" \"integer numiterations\" 64 \"float radius\" 0.05\n" + world(""));
  EXPECT_EQ(sppm.scene.settings.integrator, IntegratorType::sppm);
  EXPECT_EQ(sppm.scene.settings.max_depth, 5);  // pbrt-v3's default
  EXPECT_EQ(sppm.warnings, "");
  PbrtScene mlt = import("Integrator \"mlt\"\n" + world(""));
  EXPECT_EQ(mlt.scene.settings.integrator, IntegratorType::bdpt);
  EXPECT_NE(mlt.warnings.find("integrator \"mlt\" is not implemented: rendering with \"bdpt\""), std::string::npos)
      << mlt.warnings;
  // volpath is pbrt-v3's path tracer with media, which ours is: no substitution.
  PbrtScene volpath = import("Integrator \"volpath\" \"integer maxdepth\" 9 \"float rrthreshold\" 0.5\n" + world(""));
  EXPECT_EQ(volpath.scene.settings.integrator, IntegratorType::path);
  EXPECT_EQ(volpath.scene.settings.max_depth, 9);
  EXPECT_EQ(volpath.warnings, "");
}

// pbrt-v3 makes a material for the shapes that use it: one overridden before
// any shape (or a texture only such a material reads) is no error, not even
// when nothing here could render it; once a shape uses it, its error is the
// same, at the directive that asks for it.
TEST(PbrtImport, WhatNoShapeUsesIsNoError) {
  PbrtScene scene = import(world(
      "Texture \"odd\" \"spectrum\" \"ptex\"\n"
      "Material \"hair\"\n"
      "Material \"matte\" \"texture Kd\" \"odd\"\n"
      "MakeNamedMaterial \"m\" \"string type\" \"fourier\"\n"
      "MakeNamedMaterial \"m\" \"string type\" \"matte\" \"rgb Kd\" [0.2 0.3 0.4]\n"
      "NamedMaterial \"m\"\nShape \"sphere\""));
  ASSERT_EQ(scene.scene.shapes.size(), 1u);
  EXPECT_EQ(sg::raw(diffuse(scene.scene.materials.at(scene.scene.shapes[0].material)).value),
            glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_EQ(import_error(world("Material \"hair\"\nAttributeBegin\nShape \"sphere\"\nAttributeEnd")),
            "scene.pbrt:2:10: error: material \"hair\" is not supported\nMaterial \"hair\"\n"
            "         ^~~~~~\nhelp: supported: \"matte\", \"mirror\", \"plastic\", \"glass\", \"metal\", \"substrate\", "
            "\"translucent\", \"uber\", \"mix\", \"disney\"\n");
  EXPECT_EQ(import_error(world("Texture \"odd\" \"spectrum\" \"ptex\"\nMaterial \"plastic\" \"texture Kd\" \"odd\"\n"
                               "Shape \"sphere\"")),
            "scene.pbrt:2:26: error: texture \"ptex\" is not supported\nTexture \"odd\" \"spectrum\" \"ptex\"\n"
            "                         ^~~~~~\nhelp: supported: \"constant\", \"imagemap\", \"scale\", \"mix\", \"checkerboard\", "
            "\"dots\", \"fbm\", \"wrinkled\", \"windy\", \"marble\", \"uv\", \"bilerp\"\n");
}

// pbrt-v3's procedural textures become Scene patterns with their parameters;
// the solid ones read texture space through the Texture's transform, in the
// scene's length unit.
TEST(PbrtImport, ProceduralTexturesKeepTheirParameters) {
  PbrtScene scene = import(world(
      "Texture \"t\" \"color\" \"checkerboard\" \"float uscale\" [8] \"float vscale\" [4] \"rgb tex1\" [.1 .1 .1] \"rgb tex2\" [.8 .8 .8]\n"
      "Material \"plastic\" \"texture Kd\" \"t\"\nShape \"sphere\"\n"
      "Texture \"m\" \"spectrum\" \"marble\" \"integer octaves\" [16] \"float roughness\" [0.75] \"float scale\" [5] \"float variation\" [0.75]\n"
      "Material \"matte\" \"texture Kd\" \"m\"\nShape \"sphere\"\n"
      "Texture \"w\" \"color\" \"wrinkled\" \"integer octaves\" [4]\n"
      "Texture \"s\" \"color\" \"scale\" \"texture tex1\" \"w\" \"rgb tex2\" [.5 .5 .5]\n"
      "Material \"matte\" \"texture Kd\" \"s\"\nShape \"sphere\""));
  ASSERT_EQ(scene.scene.patterns.size(), 3u);
  const auto& checks = std::get<CheckerboardPattern>(scene.scene.patterns[0].pattern);
  EXPECT_EQ(checks.mapping.u_scale, 8.0f);
  EXPECT_EQ(checks.mapping.v_scale, 4.0f);
  EXPECT_EQ(sg::raw(checks.even)[0], 0.1f);
  EXPECT_EQ(sg::raw(checks.odd)[0], 0.8f);
  EXPECT_TRUE(checks.box_filtered);
  const auto& marble = std::get<MarblePattern>(scene.scene.patterns[1].pattern);
  EXPECT_EQ(marble.octaves, 16);
  EXPECT_EQ(marble.omega, 0.75f);
  EXPECT_EQ(marble.scale, 5.0f);
  EXPECT_EQ(marble.variation, 0.75f);
  const auto& wrinkles = std::get<FbmPattern>(scene.scene.patterns[2].pattern);
  EXPECT_TRUE(wrinkles.turbulence);
  EXPECT_EQ(wrinkles.octaves, 4);
  ASSERT_EQ(scene.scene.materials.size(), 3u);
  EXPECT_EQ(diffuse(scene.scene.materials[0]).pattern, 0);
  EXPECT_EQ(diffuse(scene.scene.materials[1]).pattern, 1);
  const TexturedReflectance scaled = diffuse(scene.scene.materials[2]);  // scale: a constant times the pattern
  EXPECT_EQ(scaled.pattern, 2);
  EXPECT_EQ(sg::raw(scaled.value)[0], 0.5f);
}

TEST(PbrtImport, SolidTexturesFollowTheirTransformAndTheLengthUnit) {
  // Under Scale 2, a 3D checkerboard's cubes are 2 pbrt units: 2 cm here,
  // with a face at each axis's 0 (the importer may mirror x, so the test
  // compares neighbours rather than naming which colour is where).
  PbrtScene scene = import(world("Scale 2 2 2\n"
                                 "Texture \"t\" \"color\" \"checkerboard\" \"integer dimension\" [3]\nIdentity\n"
                                 "Material \"matte\" \"texture Kd\" \"t\"\nShape \"sphere\""),
                           in_memory({}, 0.01));
  ASSERT_EQ(scene.scene.patterns.size(), 1u);
  const Pattern& cubes = scene.scene.patterns[0].pattern;
  auto at = [&](float x, float y = 0.005f) {
    PatternLookup lookup{.position = sg::from_raw<PointWorld>(sg::vec3_rep(x, y, 0.005f))};
    return sg::raw(evaluate(cubes, lookup))[0];
  };
  const float first = at(0.01f);
  EXPECT_TRUE(first == 0 || first == 1) << first;  // tex1's default 1, tex2's 0
  EXPECT_EQ(at(0.019f), first);
  EXPECT_EQ(at(0.021f), 1 - first);
  EXPECT_EQ(at(0.041f), first);
  EXPECT_EQ(at(-0.001f), 1 - first);
  EXPECT_EQ(at(0.01f, 0.019f), first);
  EXPECT_EQ(at(0.01f, 0.021f), 1 - first);
}

// The other 2D mappings read the point where pbrt-v3 has it: spherical and cylindrical in the space of the
// Texture's transform (here translated by +1 along pbrt's z), planar in pbrt's world, both un-mirrored from
// ours (see Handedness) and in scene units. Spheres mark pbrt-world points (1, 0, 0), (0, 3, 0), (0, 0, 2).
TEST(PbrtImport, TwoDimensionalMappingsReadThePointAsPbrtV3Does) {
  auto marker = [](const char* at) {
    return "AttributeBegin\nTranslate " + std::string(at) + "\nShape \"sphere\" \"float radius\" 0.1\nAttributeEnd\n";
  };
  PbrtScene scene = import(world(
      "TransformBegin\nTranslate 0 0 1\n"
      "Texture \"s\" \"color\" \"checkerboard\" \"string mapping\" \"spherical\"\n"
      "Texture \"c\" \"color\" \"dots\" \"string mapping\" \"cylindrical\"\nTransformEnd\n"
      "Texture \"p\" \"color\" \"checkerboard\" \"string mapping\" \"planar\" \"vector v2\" [0 0 1] \"float udelta\" 0.25\n"
      "Material \"matte\" \"texture Kd\" \"s\"\n" +
      marker("1 0 0") + marker("0 3 0") + marker("0 0 2") +
      "Material \"matte\" \"texture Kd\" \"c\"\nShape \"sphere\"\nMaterial \"matte\" \"texture Kd\" \"p\"\nShape \"sphere\""));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.patterns.size(), 3u);
  auto centre = [&](int shape) { return s.shapes[shape].render_from_object(s.shapes[shape].center); };
  auto st = [&](int pattern, int shape) {
    const Mapping2D& m = std::visit([](const auto& p) -> const Mapping2D& {
      if constexpr (requires { p.mapping.kind; }) return p.mapping;
      else throw std::logic_error("a solid pattern");
    }, s.patterns[pattern].pattern);
    return m.at(0, 0, centre(shape));
  };
  // Spherical about pbrt's (0, 0, 1): (1, 0, -1) is θ = 3π/4, φ = 0; (0, 3, -1) is φ = π/2; (0, 0, 1) is the pole.
  EXPECT_NEAR(st(0, 0).s, 0.75f, 1e-5f);
  EXPECT_NEAR(st(0, 0).t, 0.0f, 1e-5f);
  EXPECT_NEAR(st(0, 1).t, 0.25f, 1e-5f);
  EXPECT_NEAR(st(0, 2).s, 0.0f, 1e-5f);
  // Cylindrical about the same: (1, 0, -1)/√2 gives s = (π + 0)/2π, t = -1/√2.
  EXPECT_NEAR(st(1, 0).s, 0.5f, 1e-5f);
  EXPECT_NEAR(st(1, 0).t, -std::sqrt(0.5f), 1e-5f);
  // Planar in pbrt's world: (0.25 + x, z).
  EXPECT_NEAR(st(2, 0).s, 1.25f, 1e-5f);
  EXPECT_NEAR(st(2, 1).s, 0.25f, 1e-5f);
  EXPECT_NEAR(st(2, 2).t, 2.0f, 1e-5f);
}

TEST(PbrtImport, ProceduralTextureErrorsNameTheParameter) {
  // A float pattern is a bump map's; as a roughness, it is refused where the material reads it.
  EXPECT_EQ(import_error(world(used_float_texture("Texture \"t\" \"float\" \"fbm\""))),
            "scene.pbrt:3:20: error: a procedural texture as \"roughness\" of Material \"plastic\" is not supported\n"
            "Material \"plastic\" \"texture roughness\" \"t\"\n                   ^~~~~~~~~~~~~~~~~~~\n"
            "help: only \"bumpmap\" reads a float texture here; the others take numbers\n");
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"color\" \"dots\" \"string mapping\" \"cubic\""))),
            "scene.pbrt:2:28: error: texture mapping \"cubic\" is unknown\n"
            "Texture \"t\" \"color\" \"dots\" \"string mapping\" \"cubic\"\n"
            "                           ^~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 has \"uv\", \"spherical\", \"cylindrical\" and \"planar\" (and would use \"uv\")\n");
  EXPECT_EQ(import_error(world(used_texture("Texture \"t\" \"color\" \"checkerboard\" \"rgb tex1\" [2 0 0]"))),
            "scene.pbrt:2:36: error: \"tex1\" of Texture \"t\" must lie in [0, 1] in every channel\n"
            "Texture \"t\" \"color\" \"checkerboard\" \"rgb tex1\" [2 0 0]\n"
            "                                   ^~~~~~~~~~\n"
            "help: above 1 a surface reflects more light than it receives\n");
  EXPECT_EQ(import_error(world(used("Texture \"t\" \"color\" \"fbm\"\nMaterial \"mirror\" \"texture Kr\" \"t\""))),
            "scene.pbrt:3:19: error: a procedural texture as \"Kr\" of Material \"mirror\" is not supported\n"
            "Material \"mirror\" \"texture Kr\" \"t\"\n                  ^~~~~~~~~~~~\n"
            "help: only diffuse reflectances (\"Kd\" of matte, plastic, substrate, translucent and uber) take textures here\n");
}

}  // namespace
}  // namespace safegi::render

namespace safegi::render {
namespace {

using namespace pbrt_test;

struct Extent {
  glm::dvec3 lower{1e30}, upper{-1e30};
};
Extent extent_of(const Shape& shape) {
  Extent e;
  for (const PointObject& p : shape.positions) {
    const glm::dvec3 v(sg::raw(shape.render_from_object(p)));
    e.lower = glm::min(e.lower, v);
    e.upper = glm::max(e.upper, v);
  }
  return e;
}

// pbrt-v3's curves as meshes: a tube of the curve's width ("cylinder"; "flat"
// too, warned), a strip across normals ("ribbon"); B-splines converted to
// Bézier segments as pbrt-v3 converts them (a uniform cubic B-spline starts at
// (p0 + 4 p1 + p2) / 6).
TEST(PbrtImportCurves, TubesRibbonsAndBSplines) {
  const std::string line = "\"point P\" [0 0 0 1 0 0 2 0 0 3 0 0] \"float width\" 0.5";
  PbrtScene scene = import(world("Shape \"curve\" " + line + " \"string type\" \"cylinder\"\n"
                                 "Shape \"curve\" " + line + " \"string type\" \"ribbon\" \"normal N\" [0 0 1 0 0 1]\n"
                                 "Shape \"curve\" " + line + " \"string type\" \"cylinder\" \"string basis\" \"bspline\"\n"));
  ASSERT_EQ(scene.scene.shapes.size(), 3u);
  const Shape& tube = scene.scene.shapes[0];
  EXPECT_EQ(tube.indices.size(), 3u * 16 * 8 * 2);  // 16 steps along, 8 sides, 2 triangles each
  const Extent t = extent_of(tube);
  EXPECT_NEAR(t.upper.x - t.lower.x, 3, 1e-6);
  for (int axis : {1, 2}) {
    EXPECT_LE(t.upper[axis], 0.25 + 1e-6);
    EXPECT_GE(t.lower[axis], -0.25 - 1e-6);
  }
  ASSERT_EQ(tube.normals.size(), tube.positions.size());
  for (const auto& n : tube.normals) {
    EXPECT_NEAR(sg::raw(n).x, 0, 1e-6);  // around the x axis
  }
  const Shape& ribbon = scene.scene.shapes[1];
  double area = 0;
  for (size_t i = 0; i < ribbon.indices.size(); i += 3) {
    const glm::dvec3 a(sg::raw(ribbon.positions[ribbon.indices[i]])), b(sg::raw(ribbon.positions[ribbon.indices[i + 1]])),
        c(sg::raw(ribbon.positions[ribbon.indices[i + 2]]));
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  EXPECT_NEAR(area, 0.5 * 3, 1e-5);  // width × length
  EXPECT_NEAR(extent_of(ribbon).upper.z - extent_of(ribbon).lower.z, 0, 1e-6);  // flat, across its normals
  const Extent b = extent_of(scene.scene.shapes[2]);
  EXPECT_NEAR(b.upper.x - b.lower.x, 1, 1e-6);  // from (0 + 4 + 2) / 6 to (1 + 8 + 3) / 6
  EXPECT_EQ(scene.warnings, "");
  EXPECT_NE(import(world("Shape \"curve\" " + line)).warnings.find("warning: a flat curve is rendered as a tube of its width"),
            std::string::npos);
}

TEST(PbrtImportCurves, Errors) {
  EXPECT_EQ(first_line(import_error(world("Shape \"curve\" \"point P\" [0 0 0 1 0 0 2 0 0 3 0 0 4 0 0]"))),
            "scene.pbrt:2:7: error: Shape \"curve\": a degree 3 Bézier curve needs 4 + k·3 control points, found 5");
  EXPECT_EQ(first_line(import_error(world("Shape \"curve\" \"point P\" [0 0 0 1 0 0 2 0 0 3 0 0] \"string type\" \"ribbon\""))),
            "scene.pbrt:2:7: error: Shape \"curve\": a ribbon needs \"normal N\", one per segment end: 2 normals");
  EXPECT_EQ(first_line(import_error(world("Shape \"curve\" \"point P\" [0 0 0 1 0 0 2 0 0] \"integer degree\" 2 "
                                          "\"string basis\" \"nurbs\""))),
            "scene.pbrt:2:64: error: unknown basis \"nurbs\"");
  EXPECT_EQ(first_line(import_error(world("Shape \"curve\""))),
            "scene.pbrt:2:7: error: Shape \"curve\" needs \"point P\": its control points, x y z each");
  // A hair file's worth of curves is refused before it is made, not swapped for.
  MemoryLimit limit("1MiB");
  std::string many;
  for (int i = 0; i < 40; ++i) many += "Shape \"curve\" \"point P\" [0 0 0 1 0 0 2 0 0 3 0 0]\n";
  const std::string error = first_line(import_error(world(many)));
  EXPECT_NE(error.find("error: Shape \"curve\": the scene's curves make "), std::string::npos) << error;
  EXPECT_NE(error.find(" triangles so far, more than fit in 80 % of the 1.0 MiB available (SAFEGI_RENDER_MEMORY_LIMIT)"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace safegi::render
