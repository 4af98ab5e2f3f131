#include "lights/light_choice.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

namespace safegi::render {
namespace {

PointWorld at(Real x, Real y, Real z) { return from_kernel<PointWorld>(kernel::Real3{x, y, z}); }

TEST(LightChoice, CdfIsNormalisedAndUniformWithoutWeights) {
  EXPECT_EQ(light_cdf(std::vector<double>{1, 3}), (std::vector<Real>{Real(0.25), Real(1)}));
  EXPECT_EQ(light_cdf(std::vector<double>{0, 0}), (std::vector<Real>{Real(0.5), Real(1)}));
  EXPECT_EQ(light_cdf(std::vector<double>{1, std::numeric_limits<double>::infinity()}),
            (std::vector<Real>{Real(0.5), Real(1)}));
}

TEST(LightChoice, ChoiceRescalesItsNumberWithinTheShare) {
  const std::vector<Real> cdf{Real(0.25), Real(1)};
  ChosenLight first = choose_light(cdf, Real(0.125));
  EXPECT_EQ(first.index, 0u);
  EXPECT_FLOAT_EQ(first.probability, 0.25f);
  EXPECT_FLOAT_EQ(first.u_within, 0.5f);
  ChosenLight second = choose_light(cdf, Real(0.5));
  EXPECT_EQ(second.index, 1u);
  EXPECT_FLOAT_EQ(second.probability, 0.75f);
  EXPECT_NEAR(second.u_within, 1.0 / 3, 1e-6);
  EXPECT_LT(choose_light(cdf, Real(0x1.fffffep-1f)).u_within, Real(1));
}

// Light 0 lights only the box's half x < 0.5, light 1 everywhere alike.
TEST(LightChoice, SpatialWeighsEachVoxelByWhatReachesIt) {
  kernel::Bounds3 box;
  box.extend(kernel::Real3{0, 0, 0});
  box.extend(kernel::Real3{1, 1, 1});
  std::atomic<int> calls{0};
  SpatialLightChoice choice(box, 2, [&](uint32_t light, PointWorld p, Real, Real, Real) {
    ++calls;
    return light == 1 || to_kernel(p).x < Real(0.5) ? 1.0 : 0.0;
  });
  std::span<const Real> near = choice.cdf_at(at(0.1f, 0.5f, 0.5f));
  EXPECT_FLOAT_EQ(light_probability(near, 0), 0.5f);
  EXPECT_EQ(calls.load(), 2 * SpatialLightChoice::kSamplesPerVoxel);
  // Never nothing: a thousandth of the mean contribution at least.
  std::span<const Real> far = choice.cdf_at(at(0.9f, 0.5f, 0.5f));
  EXPECT_GT(light_probability(far, 0), 0.0f);
  EXPECT_LT(light_probability(far, 0), 1e-3f);
  // A voxel is computed once, however many threads ask; points outside the box go to the nearest voxel.
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) threads.emplace_back([&] { choice.cdf_at(at(0.1f, 0.5f, 0.5f)); });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(calls.load(), 4 * SpatialLightChoice::kSamplesPerVoxel);
  EXPECT_EQ(choice.cdf_at(at(-5, 0.5f, 0.5f)).data(), choice.cdf_at(at(0, 0.5f, 0.5f)).data());
  EXPECT_EQ(choice.cdf_at(at(std::nanf(""), 0.5f, 0.5f)).data(), choice.cdf_at(at(0, 0.5f, 0.5f)).data());
}

// Many lights, fewer points a voxel: 128 up to 64 lights, then 128 · 64 / lights, at least 8.
TEST(LightChoice, ManyLightsTakeFewerPointsAVoxel) {
  EXPECT_EQ(SpatialLightChoice::samples_per_voxel(2), 128);
  EXPECT_EQ(SpatialLightChoice::samples_per_voxel(64), 128);
  EXPECT_EQ(SpatialLightChoice::samples_per_voxel(128), 64);
  EXPECT_EQ(SpatialLightChoice::samples_per_voxel(2000), 8);
  kernel::Bounds3 box;
  box.extend(kernel::Real3{0, 0, 0});
  box.extend(kernel::Real3{1, 1, 1});
  std::atomic<int> calls{0};
  SpatialLightChoice choice(box, 1000, [&](uint32_t light, PointWorld, Real, Real, Real) {
    ++calls;
    return light % 2 == 0 ? 1.0 : 0.0;
  });
  std::span<const Real> cdf = choice.cdf_at(at(0.5f, 0.5f, 0.5f));
  EXPECT_EQ(calls.load(), 8 * 1000);
  EXPECT_NEAR(light_probability(cdf, 0), 1.0 / 500, 1e-5);  // the odd ones at the floor, 1/1000 of the mean
  EXPECT_GT(light_probability(cdf, 1), 0.0f);
}

}  // namespace
}  // namespace safegi::render
