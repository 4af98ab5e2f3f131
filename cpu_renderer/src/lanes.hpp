// Four lanes of the kernel's Real in one vector (GCC/Clang vector extensions:
// SSE on any x86-64), as the BVH's box test, its build's binning and the
// triangle blocks' test use them.
#pragma once

#include "safegi/cpu_renderer/kernel_math.hpp"

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace safegi::render::kernel {

using Lanes4 = Real __attribute__((vector_size(4 * sizeof(Real))));
// What comparing two Lanes4 gives: all bits set in a lane where it holds.
using LaneMask4 = decltype(Lanes4{} < Lanes4{});

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

}  // namespace safegi::render::kernel
