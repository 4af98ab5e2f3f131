// Adding a float quantity to a double one (the double build next to float code).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length, double> total(quantity<dim::length, float> a, quantity<dim::length, double> b) {
#ifndef FIXED
  return a + b;
#else
  return from_raw<quantity<dim::length, double>>(raw(a)) + b;
#endif
}
}  // namespace cf

int main() { return 0; }
