#include "textures/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace safegi::render {
namespace {

// Perlin's permutation of 0..255 (his reference implementation's, which
// pbrt-v3 uses), looked up twice over so that p[p[x] + y] needs no wrap.
constexpr std::array<unsigned char, 256> kPermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

int permute(int i) { return kPermutation[i & 255]; }

// The lattice point's gradient (one of 12 edge directions of a cube, 4 of
// them twice: pbrt-v3's choice) dotted with the offset from it.
Real gradient_dot(int x, int y, int z, Real dx, Real dy, Real dz) {
  const int h = permute(permute(permute(x) + y) + z) & 15;
  const Real u = h < 8 || h == 12 || h == 13 ? dx : dy;
  const Real v = h < 4 || h == 12 || h == 13 ? dy : dz;
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// 6t⁵ − 15t⁴ + 10t³: zero first and second derivatives at 0 and 1.
Real fade(Real t) { return t * t * t * (t * (t * 6 - 15) + 10); }

Real lerp(Real t, Real a, Real b) { return (1 - t) * a + t * b; }

Real smooth_step(Real low, Real high, Real value) {
  const Real v = std::clamp((value - low) / (high - low), Real(0), Real(1));
  return v * v * (3 - 2 * v);
}

// The lattice cell of a coordinate (modulo the period) and the offset in it;
// fmod first, so that no coordinate is converted to int out of its range.
int cell(Real coordinate, Real& offset) {
  const Real floor = std::floor(coordinate);
  offset = coordinate - floor;
  return static_cast<int>(std::fmod(floor, Real(256))) & 255;
}

// pbrt-v3's octave count for a footprint: n = −1 − log2(footprint), clamped
// to [0, max_octaves] (a zero footprint keeps them all).
Real octave_count(Real footprint, int max_octaves) {
  const Real limit = static_cast<Real>(std::max(max_octaves, 0));
  if (!(footprint > 0)) return limit;
  return std::clamp(-1 - std::log2(footprint), Real(0), limit);
}

NoisePoint scaled(NoisePoint p, Real factor) { return {p.x * factor, p.y * factor, p.z * factor}; }

}  // namespace

Real perlin_noise(NoisePoint p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;
  Real dx, dy, dz;
  const int ix = cell(p.x, dx), iy = cell(p.y, dy), iz = cell(p.z, dz);
  auto corner = [&](int i, int j, int k) { return gradient_dot(ix + i, iy + j, iz + k, dx - i, dy - j, dz - k); };
  const Real wx = fade(dx), wy = fade(dy), wz = fade(dz);
  const Real y0 = lerp(wy, lerp(wx, corner(0, 0, 0), corner(1, 0, 0)), lerp(wx, corner(0, 1, 0), corner(1, 1, 0)));
  const Real y1 = lerp(wy, lerp(wx, corner(0, 0, 1), corner(1, 0, 1)), lerp(wx, corner(0, 1, 1), corner(1, 1, 1)));
  return lerp(wz, y0, y1);
}

Real perlin_noise(Real x, Real y) { return perlin_noise({x, y, Real(0.5)}); }

Real fbm(NoisePoint p, Real footprint, Real omega, int max_octaves) {
  const Real n = octave_count(footprint, max_octaves);
  const int whole = static_cast<int>(n);
  Real sum = 0, frequency = 1, amplitude = 1;
  for (int i = 0; i < whole; ++i) {
    sum += amplitude * perlin_noise(scaled(p, frequency));
    frequency *= Real(1.99);
    amplitude *= omega;
  }
  return sum + amplitude * smooth_step(Real(0.3), Real(0.7), n - whole) * perlin_noise(scaled(p, frequency));
}

Real turbulence(NoisePoint p, Real footprint, Real omega, int max_octaves) {
  const Real n = octave_count(footprint, max_octaves);
  const int whole = static_cast<int>(n);
  Real sum = 0, frequency = 1, amplitude = 1;
  for (int i = 0; i < whole; ++i) {
    sum += amplitude * std::abs(perlin_noise(scaled(p, frequency)));
    frequency *= Real(1.99);
    amplitude *= omega;
  }
  sum += amplitude * lerp(smooth_step(Real(0.3), Real(0.7), n - whole), Real(0.2), std::abs(perlin_noise(scaled(p, frequency))));
  for (int i = whole; i < max_octaves; ++i) {
    sum += amplitude * Real(0.2);
    amplitude *= omega;
  }
  return sum;
}

}  // namespace safegi::render
