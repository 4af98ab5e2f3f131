// Raising a dimension to a power whose exponent leaves int: g++ rejects the
// template argument ("overflow in constant expression"); no wrap-around.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <climits>
#include <type_traits>

#include <safegi/typed/dimension.hpp>

using namespace safegi;

namespace cf {
using half = dim::pow<dim::length, INT_MAX / 2 + 1>;
#ifndef FIXED
using squared = dim::pow<half, 2>;
#else
using squared = dim::pow<half, 1>;
#endif
static_assert(!std::is_same_v<squared, dim::dimensionless>);
}  // namespace cf

int main() { return 0; }
