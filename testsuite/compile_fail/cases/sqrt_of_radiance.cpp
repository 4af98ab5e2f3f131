// Square root of radiance.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::radiance> rms(quantity<dim::radiance> a, quantity<dim::radiance> b) {
#ifndef FIXED
  return safegi::sqrt(a * a + b);
#else
  return safegi::sqrt(a * a + b * b);
#endif
}
}  // namespace cf

int main() { return 0; }
