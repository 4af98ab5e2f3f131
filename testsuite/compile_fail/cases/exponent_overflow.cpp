// Multiplying dimensions whose exponents sum beyond int: an error, not a wrap.
// The largest exponents (INT_MAX and its negation) are dimensions like any other.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <climits>
#include <type_traits>

#include <safegi/typed/dimension.hpp>

using namespace safegi;

namespace cf {
using huge = dim::pow<dim::length, INT_MAX>;
static_assert(std::is_same_v<dim::product<huge, dim::inverse<huge>>, dim::dimensionless>);
static_assert(std::is_same_v<dim::quotient<huge, dim::length>, dim::pow<dim::length, INT_MAX - 1>>);
#ifndef FIXED
using beyond = dim::product<huge, dim::length>;
#else
using beyond = dim::quotient<huge, dim::length>;
#endif
inline beyond* unused = nullptr;
}  // namespace cf

int main() { return 0; }
