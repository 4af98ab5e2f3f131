// Taking acos of a length.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::angle> f(quantity<dim::length> d, quantity<dim::length> r) {
  (void)r;
#ifndef FIXED
  return safegi::acos(d);
#else
  return safegi::acos(d / r);
#endif
}
}  // namespace cf

int main() { return 0; }
