// Exponentiating a length (Beer-Lambert without the coefficient).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
float transmittance(quantity<dim::length> d, quantity<dim::pdf_length> sigma_t) {
  (void)sigma_t;
#ifndef FIXED
  return safegi::exp(-d);
#else
  return safegi::exp(-sigma_t * d);
#endif
}
}  // namespace cf

int main() { return 0; }
