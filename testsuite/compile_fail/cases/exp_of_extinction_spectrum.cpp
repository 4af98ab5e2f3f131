// Exponentiating an extinction coefficient without the distance.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/spectrum.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::dimensionless> transmittance(spectrum<dim::pdf_length> sigma_t, quantity<dim::length> d) {
  (void)d;
#ifndef FIXED
  return safegi::exp(-sigma_t);
#else
  return safegi::exp(-sigma_t * d);
#endif
}
}  // namespace cf

int main() { return 0; }
