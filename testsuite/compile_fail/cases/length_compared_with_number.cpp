// Comparing a length with a plain number.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
bool far(quantity<dim::length> d) {
#ifndef FIXED
  return d > 100.0f;
#else
  return d > 100.0f * units::metre;
#endif
}
}  // namespace cf

int main() { return 0; }
