// Adding a plain number to a length.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> offset(quantity<dim::length> d) {
#ifndef FIXED
  return d + 0.001f;
#else
  return d + 1.0f * units::millimetre;
#endif
}
}  // namespace cf

int main() { return 0; }
