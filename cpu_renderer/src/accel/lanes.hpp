// Four lanes of the kernel's Real in one vector (GCC/Clang vector extensions:
// SSE on any x86-64), as the BVH's box test, its build's binning and the
// triangle blocks' test use them; eight for the AVX2 traversal's box test of
// an eight-wide node (one AVX register; the SSE traversal takes two Lanes4).
#pragma once

#include <cstring>

#include "safegi/cpu_renderer/kernel_math.hpp"

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace safegi::render::kernel {

using Lanes4 = Real __attribute__((vector_size(4 * sizeof(Real))));
// What comparing two Lanes4 gives: all bits set in a lane where it holds.
using LaneMask4 = decltype(Lanes4{} < Lanes4{});

using Lanes8 = Real __attribute__((vector_size(8 * sizeof(Real))));
using LaneMask8 = decltype(Lanes8{} < Lanes8{});

template <int Width>
struct LanesOf;
template <>
struct LanesOf<4> {
  using Type = Lanes4;
};
template <>
struct LanesOf<8> {
  using Type = Lanes8;
};

// Bit i set where lane i of `mask` holds. Taken by reference: in the double
// build the lanes are 32 bytes, which GCC warns would pass differently by
// value with AVX.
inline unsigned lane_bits(const LaneMask4& mask) {
#if defined(__SSE__)
  if constexpr (sizeof(LaneMask4) == sizeof(__m128))  // float lanes: one instruction
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<const __m128&>(mask)));
#endif
  unsigned bits = 0;
  for (int i = 0; i < 4; ++i) bits |= static_cast<unsigned>(mask[i] != 0) << i;
  return bits;
}

// The same of eight lanes, as two halves of four: one movemask each, in SSE
// code and in the AVX2 traversal alike (an AVX intrinsic could not be inlined
// into the SSE build of the same function).
inline unsigned lane_bits(const LaneMask8& mask) {
  LaneMask4 low, high;
  std::memcpy(&low, &mask, sizeof low);
  std::memcpy(&high, reinterpret_cast<const char*>(&mask) + sizeof low, sizeof high);
  return lane_bits(low) | lane_bits(high) << 4;
}

}  // namespace safegi::render::kernel
