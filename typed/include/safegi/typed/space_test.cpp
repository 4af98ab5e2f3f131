#include "safegi/typed/space.hpp"

#include <gtest/gtest.h>

#include <type_traits>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
struct object : space_tag<"object"> {};

using len = quantity<dim::length>;

// Layout proofs: every kind is its GLM vector.
static_assert(sizeof(point<world>) == sizeof(glm::vec3));
static_assert(sizeof(vector<world>) == sizeof(glm::vec3));
static_assert(sizeof(direction<world>) == sizeof(glm::vec3));
static_assert(sizeof(normal<world>) == sizeof(glm::vec3));
static_assert(sizeof(hpoint<world>) == sizeof(glm::vec4));
static_assert(std::is_trivially_copyable_v<point<world>>);
static_assert(std::is_trivially_copyable_v<vector<world, dim::radiance>>);
static_assert(std::is_trivially_copyable_v<direction<world>>);
static_assert(std::is_trivially_copyable_v<normal<world>>);
static_assert(std::is_trivially_copyable_v<hpoint<world>>);

// The documented result kinds and dimensions.
static_assert(std::is_same_v<decltype(point<world>{} - point<world>{}), vector<world>>);
static_assert(std::is_same_v<decltype(point<world>{} + vector<world>{}), point<world>>);
static_assert(std::is_same_v<decltype(dot(vector<world>{}, vector<world>{})), quantity<dim::area>>);
static_assert(std::is_same_v<decltype(cross(vector<world>{}, vector<world>{})), vector<world, dim::area>>);
static_assert(std::is_same_v<decltype(dot(direction<world>{}, direction<world>{})), float>);
static_assert(std::is_same_v<decltype(dot(normal<world>{}, direction<world>{})), quantity<dim::proj>>);
static_assert(std::is_same_v<decltype(dot(direction<world>{}, normal<world>{})), quantity<dim::proj>>);
static_assert(std::is_same_v<decltype(dot(normal<world>{}, normal<world>{})), float>);
static_assert(std::is_same_v<decltype(dot(normal<world>{}, vector<world>{})), len>);
static_assert(std::is_same_v<decltype(dot(direction<world>{}, vector<world>{})), len>);
static_assert(std::is_same_v<decltype(direction<world>{} * len{}), vector<world>>);
static_assert(std::is_same_v<decltype(vector<world>{} / len{}), vector<world, dim::dimensionless>>);
static_assert(std::is_same_v<decltype(length(vector<world, dim::radiance>{})), quantity<dim::radiance>>);
static_assert(std::is_same_v<decltype(distance_squared(point<world>{}, point<world>{})), quantity<dim::area>>);
static_assert(std::is_same_v<decltype(direction<world>{} + direction<world>{}), vector<world, dim::dimensionless>>);
static_assert(!std::is_same_v<point<world>, point<object>>);

point<world> at(float x, float y, float z) { return from_raw<point<world>>(glm::vec3(x, y, z)); }

TEST(Space, AffineArithmetic) {
  const point<world> a(1.0f * units::metre, 2.0f * units::metre, 3.0f * units::metre);
  const point<world> b = at(4.0f, 6.0f, 3.0f);
  const vector<world> ab = b - a;
  EXPECT_EQ(raw(ab), glm::vec3(3.0f, 4.0f, 0.0f));
  EXPECT_FLOAT_EQ(in(length(ab), units::metre), 5.0f);
  EXPECT_FLOAT_EQ(raw(length_squared(ab)), 25.0f);
  EXPECT_FLOAT_EQ(raw(distance(a, b)), 5.0f);
  EXPECT_EQ(a + ab, b);
  EXPECT_EQ(b - ab, a);
  EXPECT_EQ(ab + a, b);
  EXPECT_EQ(raw(lerp(a, b, 0.5f)), glm::vec3(2.5f, 4.0f, 3.0f));
  EXPECT_EQ(raw(barycentric(a, b, at(0, 0, 0), 0.5f, 0.5f, 0.0f)), raw(lerp(a, b, 0.5f)));
  EXPECT_FLOAT_EQ(in(a.y(), units::millimetre), 2000.0f);
}

TEST(Space, VectorAlgebra) {
  const vector<world> x(1.0f * units::metre, 0.0f * units::metre, 0.0f * units::metre);
  const vector<world> y = from_raw<vector<world>>(glm::vec3(0, 2, 0));
  EXPECT_EQ(raw(cross(x, y)), glm::vec3(0, 0, 2));
  EXPECT_FLOAT_EQ(raw(dot(x + y, y)), 4.0f);
  EXPECT_EQ(raw(-x), glm::vec3(-1, 0, 0));
  EXPECT_EQ(raw(x * 3.0f), glm::vec3(3, 0, 0));
  EXPECT_EQ(raw(2 * x), glm::vec3(2, 0, 0));
  const vector<world, dim::area> xa = x * (2.0f * units::metre);
  EXPECT_EQ(raw(xa), glm::vec3(2, 0, 0));
  vector<world> v = x;
  v += y;
  v -= x;
  v *= 2;
  v /= 4.0f;
  EXPECT_EQ(raw(v), glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(raw(v.y()), 1.0f);
}

TEST(Space, DirectionsAndNormals) {
  const direction<world> d = normalize(from_raw<vector<world>>(glm::vec3(0, 3, 4)));
  EXPECT_FLOAT_EQ(d.y(), 0.6f);
  EXPECT_FLOAT_EQ(d.z(), 0.8f);
  const normal<world> n(0, 0, 1);
  EXPECT_FLOAT_EQ(raw(dot(n, d)), 0.8f);
  EXPECT_FLOAT_EQ(raw(abs_dot(-n, d)), 0.8f);
  EXPECT_FLOAT_EQ(dot(d, d), 1.0f);
  EXPECT_FLOAT_EQ(dot(n, n), 1.0f);
  EXPECT_EQ(raw(face_forward(-n, d)), raw(n));
  EXPECT_EQ(raw(to_direction(n)), raw(n));
  EXPECT_EQ(raw(to_normal(d)), raw(d));
  const direction<world> r = reflect(d, n);
  EXPECT_NEAR(r.y(), -0.6f, 1e-6f);
  EXPECT_NEAR(r.z(), 0.8f, 1e-6f);
  EXPECT_EQ(raw(d * (5.0f * units::metre)), glm::vec3(0, 3, 4));
  EXPECT_FLOAT_EQ(raw(dot(n, from_raw<vector<world>>(glm::vec3(1, 2, 3)))), 3.0f);
  const vector<world, dim::dimensionless> half = d + direction<world>(0, 0, 1);
  EXPECT_FLOAT_EQ(raw(normalize(half)).y, 0.6f / std::sqrt(0.36f + 1.8f * 1.8f));
}

TEST(Space, ComponentsAndBounds) {
  const point<world> a = at(1, 5, -2);
  const point<world> b = at(3, -1, 0);
  EXPECT_EQ(raw(safegi::min(a, b)), glm::vec3(1, -1, -2));
  EXPECT_EQ(raw(safegi::max(a, b)), glm::vec3(3, 5, 0));
  EXPECT_FLOAT_EQ(raw(a[1]), 5.0f);
  const vector<world> v = b - a;
  EXPECT_FLOAT_EQ(raw(v[2]), 2.0f);
  EXPECT_EQ(raw(safegi::abs(v)), glm::vec3(2, 6, 2));
  EXPECT_FLOAT_EQ(direction<world>(0, 1, 0)[1], 1.0f);
  EXPECT_FLOAT_EQ(normal<world>(0, 0, 1)[2], 1.0f);
}

TEST(Space, HomogeneousPoints) {
  const hpoint<world> h(2.0f, 4.0f, 6.0f, 2.0f);
  EXPECT_EQ(raw(dehomogenize(h)), glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(h.w(), 2.0f);
}

TEST(Space, DefaultsAreUsable) {
  EXPECT_EQ(raw(point<world>{}), glm::vec3(0.0f));
  EXPECT_EQ(raw(vector<world>{}), glm::vec3(0.0f));
  EXPECT_EQ(raw(direction<world>{}), glm::vec3(0, 0, 1));
  EXPECT_EQ(raw(normal<world>{}), glm::vec3(0, 0, 1));
  EXPECT_EQ(raw(hpoint<world>{}), glm::vec4(0, 0, 0, 1));
}

// Unit vectors with each other and with vectors, as in the shader language: any two of
// vector, direction and normal in one space give a vector when the dimensions agree.
using unitless = vector<world, dim::dimensionless>;
static_assert(std::is_same_v<decltype(normal<world>{} - normal<world>{}), unitless>);
static_assert(std::is_same_v<decltype(normal<world>{} + normal<world>{}), unitless>);
static_assert(std::is_same_v<decltype(normal<world>{} + direction<world>{}), unitless>);
static_assert(std::is_same_v<decltype(direction<world>{} - normal<world>{}), unitless>);
static_assert(std::is_same_v<decltype(unitless{} + direction<world>{}), unitless>);
static_assert(std::is_same_v<decltype(unitless{} - normal<world>{}), unitless>);
static_assert(std::is_same_v<decltype(direction<world>{} + unitless{}), unitless>);
static_assert(std::is_same_v<decltype(normal<world>{} - unitless{}), unitless>);
static_assert(std::is_same_v<decltype(cross(vector<world>{}, direction<world>{})), vector<world>>);
static_assert(std::is_same_v<decltype(cross(direction<world>{}, vector<world, dim::radiance>{})),
                             vector<world, dim::radiance>>);
static_assert(std::is_same_v<decltype(cross(vector<world>{}, normal<world>{})), vector<world>>);
static_assert(std::is_same_v<decltype(cross(normal<world>{}, vector<world>{})), vector<world>>);
static_assert(std::is_same_v<decltype(cross(normal<world>{}, direction<world>{})), unitless>);
static_assert(std::is_same_v<decltype(cross(direction<world>{}, normal<world>{})), unitless>);
static_assert(std::is_same_v<decltype(cross(normal<world>{}, normal<world>{})), unitless>);

TEST(Space, UnitVectorSumsDifferencesAndCrossProducts) {
  const normal<world> n(0.0f, 0.0f, 1.0f);
  const normal<world> ng(0.0f, 1.0f, 0.0f);
  const direction<world> w(1.0f, 0.0f, 0.0f);
  EXPECT_EQ(raw(n - ng), glm::vec3(0, -1, 1));
  EXPECT_EQ(raw(n + ng), glm::vec3(0, 1, 1));
  EXPECT_EQ(raw(n + w), glm::vec3(1, 0, 1));
  EXPECT_EQ(raw(w - n), glm::vec3(1, 0, -1));
  const unitless h = n + w;
  EXPECT_EQ(raw(h + w), glm::vec3(2, 0, 1));
  EXPECT_EQ(raw(w - h), glm::vec3(0, 0, -1));
  EXPECT_EQ(raw(normalize(n + w)), glm::normalize(glm::vec3(1, 0, 1)));
  // A tangent from a normal and a direction, and a displacement turned about a direction.
  EXPECT_EQ(raw(cross(n, w)), glm::vec3(0, 1, 0));
  EXPECT_EQ(raw(cross(w, n)), glm::vec3(0, -1, 0));
  const vector<world> v(0.0f * units::metre, 2.0f * units::metre, 0.0f * units::metre);
  EXPECT_EQ(raw(cross(v, w)), glm::vec3(0, 0, -2));
  EXPECT_EQ(raw(cross(n, v)), glm::vec3(-2, 0, 0));
  // The displacement along a unit vector needs its length: v + n * epsilon.
  EXPECT_EQ(raw(v + n * (1.0f * units::metre)), glm::vec3(0, 2, 1));
}
}  // namespace
