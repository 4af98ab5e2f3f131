#include "integrators/sampler.hpp"

#include <gtest/gtest.h>

#include <random>

namespace safegi::render {
namespace {

using namespace sampling_detail;

// Burley's formulation as written in the paper: the Sobol point at the
// scrambled index, each dimension nested-uniform scrambled. The sampler leaves
// out reversals that cancel and looks the second dimension up by bytes; its
// values must be these, bit for bit (images depend on them).
uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}
uint32_t sobol_dimension_0(uint32_t index) { return reverse_bits(index); }
uint32_t sobol_dimension_1(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1) result ^= v;
  return result;
}

Sample2 burley_2d(uint32_t pixel_seed, uint32_t sample_index, uint32_t dimension) {
  uint32_t dimension_seed = hash_combine(pixel_seed, dimension);
  uint32_t index = nested_uniform_scramble(sample_index, dimension_seed);
  return {to_unit_float(nested_uniform_scramble(sobol_dimension_0(index), hash_combine(dimension_seed, 1))),
          to_unit_float(nested_uniform_scramble(sobol_dimension_1(index), hash_combine(dimension_seed, 2)))};
}

TEST(Sampler, ValuesAreBurleysOwenScrambledSobolPoints) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    const uint32_t seed = rng(), x = rng() % 4096, y = rng() % 4096;
    const uint32_t index = trial < 1000 ? static_cast<uint32_t>(trial) : rng();
    Sampler sampler(seed, x, y, index), sampler_1d(seed, x, y, index);
    const uint32_t pixel_seed = hash_combine(hash_combine(seed, x), y);
    for (uint32_t dimension = 0; dimension < 8; ++dimension) {
      const Sample2 expected = burley_2d(pixel_seed, index, dimension);
      const Sample2 got = sampler.next_2d();
      ASSERT_EQ(got.u, expected.u) << trial << " " << dimension;
      ASSERT_EQ(got.v, expected.v) << trial << " " << dimension;
      ASSERT_EQ(sampler_1d.next_1d(), expected.u) << trial << " " << dimension;
    }
  }
}

TEST(Sampler, SecondDimensionTableIsTheGeneratorMatrix) {
  for (uint32_t bit = 0; bit < 32; ++bit)
    EXPECT_EQ(reversed_sobol_dimension_1(1u << bit), reverse_bits(sobol_dimension_1(1u << bit))) << bit;
  std::mt19937 rng(6);
  for (int i = 0; i < 10000; ++i) {
    const uint32_t index = rng();
    EXPECT_EQ(reversed_sobol_dimension_1(index), reverse_bits(sobol_dimension_1(index))) << index;
  }
}

}  // namespace
}  // namespace safegi::render
