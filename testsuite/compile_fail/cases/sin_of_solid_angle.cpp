// Taking the sine of a solid angle.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
float f(quantity<dim::solid_angle> omega) {
#ifndef FIXED
  return safegi::sin(omega);
#else
  return safegi::sin(dimension_cast<dim::angle>(omega / units::steradian));
#endif
}
}  // namespace cf

int main() { return 0; }
