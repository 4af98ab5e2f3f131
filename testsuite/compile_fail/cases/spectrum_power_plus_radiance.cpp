// Adding power to radiance.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/spectrum.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> f(spectrum<dim::radiance> L, spectrum<dim::power> phi, quantity<dim::area> a,
                          quantity<dim::projected_solid_angle> omega) {
  (void)a; (void)omega;
#ifndef FIXED
  return L + phi;
#else
  return L + phi / a / omega;
#endif
}
}  // namespace cf

int main() { return 0; }
