// Square root of a volume (an odd exponent).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
// The side of a square-based box of volume v and height h.
quantity<dim::length> side(quantity<dim::volume> v, quantity<dim::length> h) {
  (void)h;
#ifndef FIXED
  return safegi::sqrt(v);
#else
  return safegi::sqrt(v / h);
#endif
}
}  // namespace cf

int main() { return 0; }
