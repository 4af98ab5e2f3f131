#include "safegi/typed/map.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);
SAFEGI_SPACE(camera);
SAFEGI_SPACE(clip);

static_assert(std::is_same_v<decltype(map<world, camera>{} * map<object, world>{}), map<object, camera>>);
static_assert(std::is_same_v<decltype(inverse(map<object, world>{})), map<world, object>>);
static_assert(std::is_same_v<decltype(map<object, world>{}(point<object>{})), point<world>>);
static_assert(std::is_same_v<decltype(map<object, world>{}(normal<object>{})), normal<world>>);
static_assert(std::is_same_v<decltype(map<object, world>{}(vector<object, dim::area>{})), vector<world, dim::area>>);
static_assert(std::is_same_v<decltype(projective_map<camera, clip>{}(point<camera>{})), hpoint<clip>>);
static_assert(std::is_same_v<decltype(projective_map<camera, clip>{} * map<world, camera>{}), projective_map<world, clip>>);
static_assert(std::is_trivially_copyable_v<map<object, world>>);
static_assert(sizeof(map<object, world>) == 2 * sizeof(glm::mat4));

void expect_near(glm::vec3 a, glm::vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

vector<world> offset(float x, float y, float z) { return from_raw<vector<world>>(glm::vec3(x, y, z)); }

TEST(Map, TranslationMovesPointsNotVectors) {
  const auto worldFromObject = map<object, world>::translation(offset(1, 2, 3));
  const point<object> p = from_raw<point<object>>(glm::vec3(1, 1, 1));
  expect_near(raw(worldFromObject(p)), glm::vec3(2, 3, 4));
  const vector<object> v = from_raw<vector<object>>(glm::vec3(1, 1, 1));
  expect_near(raw(worldFromObject(v)), glm::vec3(1, 1, 1));
  const normal<object> n(0, 0, 1);
  expect_near(raw(worldFromObject(n)), glm::vec3(0, 0, 1));
}

TEST(Map, CompositionAppliesTheRightMapFirst) {
  const auto worldFromObject = map<object, world>::scaling(2, 2, 2);
  const auto cameraFromWorld = map<world, camera>::translation(from_raw<vector<camera>>(glm::vec3(0, 0, -5)));
  const map<object, camera> cameraFromObject = cameraFromWorld * worldFromObject;
  const point<object> p = from_raw<point<object>>(glm::vec3(1, 2, 3));
  expect_near(raw(cameraFromObject(p)), glm::vec3(2, 4, 1));
  expect_near(raw(cameraFromObject(p)), raw(cameraFromWorld(worldFromObject(p))));
}

TEST(Map, InverseUndoes) {
  const auto worldFromObject = map<object, world>::translation(offset(1, -2, 3)) *
                               map<object, object>::rotation(30.0f * units::degree, direction<object>(0, 1, 0)) *
                               map<object, object>::scaling(1, 2, 4);
  const map<world, object> objectFromWorld = inverse(worldFromObject);
  const point<object> p = from_raw<point<object>>(glm::vec3(0.3f, -0.7f, 2.0f));
  expect_near(raw(objectFromWorld(worldFromObject(p))), raw(p));
  const map<object, object> identity = objectFromWorld * worldFromObject;
  expect_near(raw(identity(p)), raw(p));
  expect_near(raw(inverse(objectFromWorld)(p)), raw(worldFromObject(p)));
}

// Under a non-uniform scale a normal transformed like a vector stops being
// perpendicular to the surface; the inverse transpose keeps it perpendicular.
TEST(Map, NormalsStayPerpendicularUnderNonUniformScale) {
  const auto worldFromObject = map<object, world>::rotation(20.0f * units::degree, direction<object>(1, 0, 0)) *
                               map<object, object>::scaling(1.0f, 4.0f, 0.5f);
  // The plane x + y + z = 1 in object space: normal (1,1,1)/√3, tangents along it.
  const normal<object> n = to_normal(normalize(from_raw<vector<object>>(glm::vec3(1, 1, 1))));
  const vector<object> t1 = from_raw<vector<object>>(glm::vec3(1, -1, 0));
  const vector<object> t2 = from_raw<vector<object>>(glm::vec3(0, 1, -1));
  const normal<world> nw = worldFromObject(n);
  EXPECT_NEAR(raw(dot(nw, worldFromObject(t1))), 0.0f, 1e-5f);
  EXPECT_NEAR(raw(dot(nw, worldFromObject(t2))), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(raw(nw)), 1.0f, 1e-6f);
  // The same unit vector transformed as a direction is not perpendicular.
  const direction<world> wrong = worldFromObject(to_direction(n));
  EXPECT_GT(std::abs(raw(dot(wrong, worldFromObject(t1)))), 0.1f);
  // And the normal matrix given to shaders agrees.
  expect_near(glm::normalize(normal_matrix(worldFromObject) * raw(n)), raw(nw));
}

TEST(Map, DirectionsStayUnitLength) {
  const auto worldFromObject = map<object, world>::scaling(3.0f, 1.0f, 1.0f);
  const direction<world> d = worldFromObject(direction<object>(0.6f, 0.8f, 0.0f));
  EXPECT_NEAR(glm::length(raw(d)), 1.0f, 1e-6f);
}

TEST(Map, LookAtAndPerspective) {
  const point<world> eye = from_raw<point<world>>(glm::vec3(0, 0, 5));
  const auto cameraFromWorld =
      map<world, camera>::look_at(eye, point<world>{}, direction<world>(0, 1, 0));
  expect_near(raw(cameraFromWorld(point<world>{})), glm::vec3(0, 0, -5));
  const auto clipFromCamera =
      projective_map<camera, clip>::perspective(90.0f * units::degree, 1.0f, 0.1f * units::metre, 100.0f * units::metre);
  const projective_map<world, clip> clipFromWorld = clipFromCamera * cameraFromWorld;
  const hpoint<clip> h = clipFromWorld(from_raw<point<world>>(glm::vec3(5, 0, 0)));
  EXPECT_NEAR(h.w(), 5.0f, 1e-5f);
  EXPECT_NEAR(dehomogenize(h).x() / (1.0f * units::metre), 1.0f, 1e-5f);  // on the frustum's edge
  const hpoint<camera> back = inverse(clipFromCamera)(clipFromCamera(cameraFromWorld(eye)));
  expect_near(raw(dehomogenize(back)), raw(cameraFromWorld(eye)));
}

TEST(Map, MatricesForShaders) {
  const auto worldFromObject = map<object, world>::translation(offset(1, 2, 3));
  EXPECT_EQ(matrix(worldFromObject)[3], glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(matrix(inverse(worldFromObject))[3], glm::vec4(-1, -2, -3, 1));
  const auto again = from_raw<map<object, world>>(raw(worldFromObject));
  EXPECT_EQ(matrix(again), matrix(worldFromObject));
  EXPECT_EQ(matrix(map<object, world>::from_matrix(matrix(worldFromObject))), matrix(worldFromObject));
}
}  // namespace
