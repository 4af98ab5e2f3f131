// Initialising a length from a plain number.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> f() {
#ifndef FIXED
  quantity<dim::length> d = 2.5f;
  return d;
#else
  quantity<dim::length> d = 2.5f * units::metre;
  return d;
#endif
}
}  // namespace cf

int main() { return 0; }
