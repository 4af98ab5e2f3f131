// Raising a length to a non-integer power.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
float f(quantity<dim::length> d, quantity<dim::length> scale) {
  (void)scale;
#ifndef FIXED
  return safegi::pow(d, 2.5f);
#else
  return safegi::pow(d / scale, 2.5f);
#endif
}
}  // namespace cf

int main() { return 0; }
