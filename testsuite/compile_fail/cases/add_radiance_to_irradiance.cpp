// Adding radiance to irradiance.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/spectrum.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> total(spectrum<dim::radiance> L, spectrum<dim::irradiance> E) {
#ifndef FIXED
  return L + E;
#else
  // A Lambertian emitter of irradiance E leaves radiance E / (pi sr proj).
  return L + E / (pi * units::steradian * units::proj);
#endif
}
}  // namespace cf

int main() { return 0; }
