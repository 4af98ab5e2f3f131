#pragma once
// Arithmetic and equality on annotation slots: known dimensions, generic terms
// (inside generic functions), the zero literal and the unknown `?`.

#include "safegi/typechecker/type.hpp"

namespace safegi::detail {

// a * b^sign. Unknown absorbs; zero acts as dimensionless. Overflow -> nothing.
std::optional<DimSlot> combine(const DimSlot& a, const DimSlot& b, int sign);
std::optional<DimSlot> raise(const DimSlot& a, long long n);
// Both known (or both generic) and equal. Zero and unknown are not "equal" here: see consistent().
bool same_dimension(const DimSlot& a, const DimSlot& b);
// Gradual consistency: unknown or zero on either side, or the same dimension.
bool consistent(const DimSlot& a, const DimSlot& b);
bool consistent(const SpaceSlot& a, const SpaceSlot& b);
// Components of an hpoint (a swizzle, an index) stay homogeneous: same space and weight, shape of `part`.
void keep_homogeneous(Type& part, const Type& whole);

}  // namespace safegi::detail
