// Adding pixels to metres (a user base dimension).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

SAFEGI_BASE_DIMENSION(pixel);

namespace cf {
quantity<pixel> f(quantity<pixel> x, quantity<dim::length> d, quantity<dim::quotient<pixel, dim::length>> density) {
  (void)density;
#ifndef FIXED
  return x + d;
#else
  return x + d * density;
#endif
}
}  // namespace cf

int main() { return 0; }
