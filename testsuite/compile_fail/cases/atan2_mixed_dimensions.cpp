// atan2 of an area and a length.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::angle> f(quantity<dim::area> y, quantity<dim::length> x) {
#ifndef FIXED
  return safegi::atan2(y, x);
#else
  return safegi::atan2(y / x, x);
#endif
}
}  // namespace cf

int main() { return 0; }
