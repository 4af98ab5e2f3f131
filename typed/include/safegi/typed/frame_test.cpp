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
}  // namespace
