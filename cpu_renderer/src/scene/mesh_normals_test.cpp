// Vertex normals from mesh files: given ones made unit length, unusable ones
// (zero, NaN) replaced by the area-weighted mean of their triangles' normals.
#include "scene/mesh_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace safegi::render {
namespace {

glm::vec3 raw(const normal<Object>& n) { return glm::vec3(sg::raw(n)); }

// A tent of two triangles over the x axis: (0,0,0) (1,0,0) (0,1,0) lies in z = 0,
// (0,0,0) (0,1,0) (0,0,1) in x = 0; corners 0 and 2 are in both.
TEST(MeshNormals, EveryUnusableNormalBecomesItsTrianglesMean) {
  auto at = [](float x, float y, float z) { return sg::from_raw<PointObject>(sg::vec3_rep(x, y, z)); };  // metres
  const std::vector<PointObject> positions = {at(0, 0, 0), at(1, 0, 0), at(0, 1, 0), at(0, 0, 1)};
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<glm::dvec3> given = {{0, 0, 0}, {0, 0, 3}, {nan, 0, 0}, {0, 0, 0}};
  const std::vector<normal<Object>> n = unit_vertex_normals(given, positions, indices);
  ASSERT_EQ(n.size(), 4u);
  EXPECT_NEAR(glm::distance(raw(n[1]), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);  // given: made unit length
  // Corners 0 and 2 (zero, NaN): both triangles, equal areas, normals +z and +x.
  EXPECT_NEAR(glm::distance(raw(n[0]), glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(raw(n[2]), glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(raw(n[3]), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);  // the second zero: its one triangle
}

}  // namespace
}  // namespace safegi::render
