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
// A product or quotient by a plain number keeps the other factor's declared
// name: `2.0 * k` of a float<inv_length in kilometer^-1> is that, not the first
// declared name of 1/length (pdf_length). `product` is a * b, or a / b.
void keep_scaled_spelling(DimSlot& product, const DimSlot& a, const DimSlot& b, bool divide);
// A result of the same dimension as some of its sources (k + k, max(k, 0.0),
// abs, mix, length) keeps their declared name when they agree on one, and
// prints as the dimension's first declared name when they do not.
void keep_shared_spelling(DimSlot& result, const std::vector<DimSlot>& sources);
// Components of an hpoint (a swizzle, an index) stay homogeneous: same space and weight, shape of `part`.
void keep_homogeneous(Type& part, const Type& whole);

}  // namespace safegi::detail
