#include "safegi/typed/geometric_normal.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/map.hpp"
#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);

static_assert(std::is_same_v<decltype(face_normal(point<world>{}, point<world>{}, point<world>{})), geometric_normal<world>>);
static_assert(std::is_same_v<decltype(-geometric_normal<world>(geometric(normal<world>{}))), geometric_normal<world>>);
static_assert(std::is_same_v<decltype(dot(geometric(normal<world>{}), direction<world>{})), quantity<dim::proj>>);
static_assert(std::is_convertible_v<geometric_normal<world>, normal<world>>);  // a normal everywhere
static_assert(sizeof(geometric_normal<world>) == sizeof(normal<world>));
static_assert(std::is_trivially_copyable_v<geometric_normal<world>>);

point<world> at(float x, float y, float z) { return from_raw<point<world>>(glm::vec3(x, y, z)); }

TEST(GeometricNormal, FaceNormalIsCounterClockwise) {
  const geometric_normal<world> ng = face_normal(at(0, 0, 0), at(1, 0, 0), at(0, 1, 0));
  EXPECT_EQ(raw(ng), glm::vec3(0, 0, 1));
  EXPECT_EQ(raw(-ng), glm::vec3(0, 0, -1));
  const normal<world> plain = ng;  // forgetting it is free
  EXPECT_EQ(raw(plain), glm::vec3(0, 0, 1));
}

TEST(GeometricNormal, RayOriginsLeaveOnTheDirectionsSide) {
  const geometric_normal<world> ng = face_normal(at(0, 0, 0), at(1, 0, 0), at(0, 1, 0));
  const quantity<dim::length> eps = 0.5f * units::metre;
  const direction<world> up(0, 0, 1), down(0, 0, -1);
  EXPECT_EQ(raw(offset_ray_origin(at(1, 1, 0), ng, eps, up)), glm::vec3(1, 1, 0.5f));
  EXPECT_EQ(raw(offset_ray_origin(at(1, 1, 0), ng, eps, down)), glm::vec3(1, 1, -0.5f));
  // A bumped shading normal tilted past the horizon would put a grazing ray's origin
  // under the surface; the geometric normal keeps it on the side the ray leaves toward.
  const direction<world> grazing = normalize(from_raw<vector<world>>(glm::vec3(1, 0, 0.05f)));
  EXPECT_GT(raw(offset_ray_origin(at(0, 0, 0), ng, eps, grazing)).z, 0.0f);
  EXPECT_EQ(raw(offset_ray_origin(at(0, 0, 0), geometric(normal<world>(0, 0, 1)), eps, up)), glm::vec3(0, 0, 0.5f));
}
}  // namespace
