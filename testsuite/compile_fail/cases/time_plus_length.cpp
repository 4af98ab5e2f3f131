// Adding a time to a length.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> f(quantity<dim::length> d, quantity<dim::time> t) {
  (void)t;
#ifndef FIXED
  return d + t;
#else
  return d + d / t * t;
#endif
}
}  // namespace cf

int main() { return 0; }
