// Reading a length in seconds.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
float f(quantity<dim::length> d) {
#ifndef FIXED
  return in(d, units::second);
#else
  return in(d, units::millimetre);
#endif
}
}  // namespace cf

int main() { return 0; }
