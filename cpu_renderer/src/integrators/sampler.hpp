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

// The points are made with their bits reversed, as Burley's nested scramble
// (reverse, Laine–Karras permutation, reverse) takes them, so that the
// reversals that cancel are left out. Sobol's first dimension (van der Corput)
// reversed is the index itself; the second, from the (x + 1) polynomial, is
// linear over GF(2) in the index's bits, so it is four lookups, one a byte of
// the index, in tables of what each byte's bits contribute. sampler_test.cpp
// checks the values against the paper's formulation, bit for bit.
struct ReversedSobolTables {
  uint32_t by_byte[4][256];
};
inline constexpr ReversedSobolTables kReversedSobolDimension1 = [] {
  ReversedSobolTables tables{};
  uint32_t basis[32];
  // Bit i of the index contributes direction number v_i, v_0 = 2^31 and
  // v_(i+1) = v_i ^ (v_i >> 1); reversed, r_0 = 1 and r_(i+1) = r_i ^ (r_i << 1).
  for (uint32_t i = 0, r = 1; i < 32; ++i, r ^= r << 1) basis[i] = r;
  for (int byte = 0; byte < 4; ++byte)
    for (uint32_t value = 0; value < 256; ++value)
      for (int bit = 0; bit < 8; ++bit)
        if (value >> bit & 1) tables.by_byte[byte][value] ^= basis[8 * byte + bit];
  return tables;
}();
inline uint32_t reversed_sobol_dimension_1(uint32_t index) {
  const auto& t = kReversedSobolDimension1.by_byte;
  return t[0][index & 0xff] ^ t[1][index >> 8 & 0xff] ^ t[2][index >> 16 & 0xff] ^ t[3][index >> 24];
}

// Burley's nested uniform scramble of x, given x with its bits reversed.
inline uint32_t scramble_reversed(uint32_t reversed, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reversed, seed));
}

inline float to_unit_float(uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

}  // namespace sampling_detail

class Sampler {
 public:
  Sampler(uint32_t seed, uint32_t pixel_x, uint32_t pixel_y, uint32_t sample_index)
      : pixel_seed_(sampling_detail::hash_combine(sampling_detail::hash_combine(seed, pixel_x), pixel_y)),
        reversed_sample_index_(sampling_detail::reverse_bits(sample_index)) {}

  // Each call consumes one dimension pair; both coordinates lie in [0, 1).
  Sample2 next_2d() {
    using namespace sampling_detail;
    const Dimension d = next_dimension();
    return {to_unit_float(scramble_reversed(d.index, hash_combine(d.seed, 1))),
            to_unit_float(scramble_reversed(reversed_sobol_dimension_1(d.index), hash_combine(d.seed, 2)))};
  }

  // next_2d's first coordinate, without the second's work.
  float next_1d() {
    using namespace sampling_detail;
    const Dimension d = next_dimension();
    return to_unit_float(scramble_reversed(d.index, hash_combine(d.seed, 1)));
  }

 private:
  // The next dimension's seed, and the point index scrambled for it (bits reversed).
  struct Dimension {
    uint32_t seed, index;
  };
  Dimension next_dimension() {
    using namespace sampling_detail;
    const uint32_t seed = hash_combine(pixel_seed_, dimension_++);
    return {seed, scramble_reversed(reversed_sample_index_, seed)};
  }

  uint32_t pixel_seed_;
  uint32_t reversed_sample_index_;
  uint32_t dimension_ = 0;
};

}  // namespace safegi::render
