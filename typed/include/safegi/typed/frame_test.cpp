#include "safegi/typed/frame.hpp"

#include <gtest/gtest.h>

#include "safegi/typed/units.hpp"

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
using shading = spaces::shading;

static_assert(std::is_same_v<decltype(frame<world>{}.to_local(direction<world>{})), direction<shading>>);
static_assert(std::is_same_v<decltype(frame<world>{}.from_local(direction<shading>{})), direction<world>>);
static_assert(std::is_same_v<decltype(cos_theta(direction<shading>{})), quantity<dim::proj>>);
static_assert(std::is_trivially_copyable_v<frame<world>>);

void expect_near(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(Frame, FromNormalIsOrthonormal) {
  for (glm::vec3 raw_n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0.48f, -0.6f, 0.64f)}) {
    const normal<world> n = to_normal(normalize(from_raw<vector<world>>(raw_n)));
    const frame<world> f = frame<world>::from_normal(n);
    EXPECT_NEAR(dot(f.tangent(), f.bitangent()), 0.0f, 1e-6f);
    EXPECT_NEAR(raw(dot(f.normal(), f.tangent())), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(raw(f.tangent())), 1.0f, 1e-6f);
    expect_near(glm::cross(raw(f.tangent()), raw(f.bitangent())), raw(n));
  }
}

TEST(Frame, LocalCosineIsTheProjectedFactor) {
  const normal<world> n = to_normal(normalize(from_raw<vector<world>>(glm::vec3(1, 2, 2))));
  const frame<world> f = frame<world>::from_normal(n);
  const direction<world> w = normalize(from_raw<vector<world>>(glm::vec3(0, 1, 3)));
  const direction<shading> local = f.to_local(w);
  EXPECT_NEAR(raw(cos_theta(local)), raw(dot(n, w)), 1e-6f);
  EXPECT_NEAR(raw(abs_cos_theta(-local)), raw(dot(n, w)), 1e-6f);
  expect_near(raw(f.from_local(local)), raw(w));
  const vector<world> v = from_raw<vector<world>>(glm::vec3(1, 2, 3));
  expect_near(raw(f.from_local(f.to_local(v))), raw(v));
  expect_near(raw(f.to_local(n)), glm::vec3(0, 0, 1));
  expect_near(raw(f.from_local(normal<shading>(0, 0, 1))), raw(n));
}

// Local spaces: shading is a normal-frame space (from_normal, arbitrary azimuth), tangent a
// tangent-frame one (from_tangent, +x along dp/du); world is neither.
static_assert(is_frame_space<shading> && !is_tangent_frame_space<shading>);
static_assert(is_frame_space<spaces::tangent> && is_tangent_frame_space<spaces::tangent>);
static_assert(!is_frame_space<world> && !is_frame_space<spaces::object>);
SAFEGI_NORMAL_FRAME_SPACE(lobe);
SAFEGI_TANGENT_FRAME_SPACE(uv_frame);
static_assert(is_frame_space<lobe> && !is_tangent_frame_space<lobe>);
static_assert(is_tangent_frame_space<uv_frame>);
static_assert(std::is_same_v<decltype(frame<world, lobe>::from_normal(normal<world>{})), frame<world, lobe>>);
static_assert(std::is_same_v<decltype(frame<world, spaces::tangent>::from_tangent(vector<world>{}, normal<world>{})),
                             frame<world, spaces::tangent>>);
static_assert(std::is_same_v<decltype(sin_theta(direction<lobe>{})), float>);
static_assert(std::is_same_v<decltype(cos_phi(direction<uv_frame>{})), float>);
static_assert(std::is_same_v<decltype(cos_delta_phi(direction<lobe>{}, direction<lobe>{})), float>);

TEST(Frame, FromTangentPutsDpDuOnX) {
  const normal<world> n = to_normal(normalize(from_raw<vector<world>>(glm::vec3(0, 0, 2))));
  // dp/du not orthogonal to n: Gram-Schmidt keeps its tangential part.
  const vector<world> dpdu = from_raw<vector<world>>(glm::vec3(3, 0, 1));
  const frame<world, spaces::tangent> tbn = frame<world, spaces::tangent>::from_tangent(dpdu, n);
  expect_near(raw(tbn.tangent()), glm::vec3(1, 0, 0));
  expect_near(raw(tbn.bitangent()), glm::vec3(0, 1, 0));
  expect_near(raw(tbn.normal()), glm::vec3(0, 0, 1));
  // A tangent-space normal-map texel (0, 0, 1) is the normal itself; (1, 0, 0) is dp/du's way.
  expect_near(raw(tbn.from_local(normal<spaces::tangent>(0, 0, 1))), raw(n));
  expect_near(raw(tbn.from_local(normal<spaces::tangent>(1, 0, 0))), glm::vec3(1, 0, 0));
  const direction<world> along_u = normalize(from_raw<vector<world>>(glm::vec3(1, 0, 1)));
  EXPECT_NEAR(cos_phi(tbn.to_local(along_u)), 1.0f, 1e-6f);
  EXPECT_NEAR(sin_phi(tbn.to_local(along_u)), 0.0f, 1e-6f);
  // from_tangent of a direction is the same frame.
  const frame<world, spaces::tangent> same = frame<world, spaces::tangent>::from_tangent(normalize(dpdu), n);
  expect_near(raw(same.tangent()), raw(tbn.tangent()));
}

TEST(Frame, PolarAnglesAndAzimuthDifferences) {
  const direction<shading> w(0.6f, 0.0f, 0.8f);
  EXPECT_NEAR(raw(cos_theta(w)), 0.8f, 1e-6f);
  EXPECT_NEAR(sin2_theta(w), 0.36f, 1e-6f);
  EXPECT_NEAR(sin_theta(w), 0.6f, 1e-6f);
  EXPECT_EQ(sin_theta(direction<shading>(0, 0, 1)), 0.0f);
  // cos(φa − φb) does not depend on the frame's arbitrary azimuth: two frames around one
  // normal, rotated against each other, agree.
  const normal<world> n = to_normal(normalize(from_raw<vector<world>>(glm::vec3(1, 2, 2))));
  const direction<world> a = normalize(from_raw<vector<world>>(glm::vec3(1, 0, 1)));
  const direction<world> b = normalize(from_raw<vector<world>>(glm::vec3(0, 1, 1)));
  const frame<world> f = frame<world>::from_normal(n);
  const frame<world> g = frame<world>::from_tangent(from_raw<vector<world>>(glm::vec3(0, 1, 0)), n);
  EXPECT_NEAR(cos_delta_phi(f.to_local(a), f.to_local(b)), cos_delta_phi(g.to_local(a), g.to_local(b)), 1e-5f);
  EXPECT_NEAR(cos_delta_phi(f.to_local(a), f.to_local(a)), 1.0f, 1e-6f);
  const direction<shading> x(1, 0, 0), y(0, 1, 0), minus_x(-1, 0, 0);
  EXPECT_NEAR(cos_delta_phi(x, y), 0.0f, 1e-6f);
  EXPECT_NEAR(cos_delta_phi(x, minus_x), -1.0f, 1e-6f);
  EXPECT_EQ(cos_delta_phi(x, direction<shading>(0, 0, 1)), 1.0f);  // the pole has no azimuth
}
}  // namespace
