// min of a length and a time.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> f(quantity<dim::length> d, quantity<dim::time> t, quantity<dim::length> far) {
  (void)t;
#ifndef FIXED
  return safegi::min(d, t);
#else
  return safegi::min(d, far);
#endif
}
}  // namespace cf

int main() { return 0; }
