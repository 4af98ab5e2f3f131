// Returning a BRDF where radiance is expected.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/spectrum.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> f(spectrum<dim::brdf> rho, spectrum<dim::irradiance> E) {
  (void)E;
#ifndef FIXED
  return rho;
#else
  return rho * E;
#endif
}
}  // namespace cf

int main() { return 0; }
