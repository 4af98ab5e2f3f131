// Storing radiance in an irradiance variable.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::irradiance> f(quantity<dim::radiance> L, quantity<dim::projected_solid_angle> omega) {
  (void)omega;
#ifndef FIXED
  quantity<dim::irradiance> E = L;
  return E;
#else
  quantity<dim::irradiance> E = L * omega;
  return E;
#endif
}
}  // namespace cf

int main() { return 0; }
