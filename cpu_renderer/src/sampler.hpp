// Deterministic per-pixel sampling: padded, Owen-scrambled Sobol points
// (Burley 2020, "Practical Hash-based Owen Scrambling").
//
// Every sample value is a pure function of (seed, pixel, sample index,
// dimension), so an image is bit-identical whatever the thread count or tile
// order, and a render can be continued sample by sample (--time-budget).
#pragma once

#include <cstdint>

namespace safegi::render {

struct Sample2 {
  float u, v;
};

namespace sampling_detail {

inline uint32_t hash_combine(uint32_t seed, uint32_t value) {
  // A 32-bit integer finaliser (Wellons' lowbias32) over the xor-mixed inputs.
  uint32_t x = seed ^ (value + 0x9e3779b9u + (seed << 6) + (seed >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

inline uint32_t reverse_bits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

inline uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// The first two Sobol dimensions: van der Corput, and the (x + 1) polynomial.
inline uint32_t sobol_dimension_0(uint32_t index) { return reverse_bits(index); }
inline uint32_t sobol_dimension_1(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1) result ^= v;
  return result;
}

inline float to_unit_float(uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

}  // namespace sampling_detail

class Sampler {
 public:
  Sampler(uint32_t seed, uint32_t pixel_x, uint32_t pixel_y, uint32_t sample_index)
      : pixel_seed_(sampling_detail::hash_combine(sampling_detail::hash_combine(seed, pixel_x), pixel_y)),
        sample_index_(sample_index) {}

  // Each call consumes one dimension pair; both coordinates lie in [0, 1).
  Sample2 next_2d() {
    using namespace sampling_detail;
    uint32_t dimension_seed = hash_combine(pixel_seed_, dimension_++);
    uint32_t index = nested_uniform_scramble(sample_index_, dimension_seed);
    uint32_t x = nested_uniform_scramble(sobol_dimension_0(index), hash_combine(dimension_seed, 1));
    uint32_t y = nested_uniform_scramble(sobol_dimension_1(index), hash_combine(dimension_seed, 2));
    return {to_unit_float(x), to_unit_float(y)};
  }

  float next_1d() {
    using namespace sampling_detail;
    uint32_t dimension_seed = hash_combine(pixel_seed_, dimension_++);
    uint32_t index = nested_uniform_scramble(sample_index_, dimension_seed);
    return to_unit_float(nested_uniform_scramble(sobol_dimension_0(index), hash_combine(dimension_seed, 1)));
  }

 private:
  uint32_t pixel_seed_;
  uint32_t sample_index_;
  uint32_t dimension_ = 0;
};

}  // namespace safegi::render
