// Passing degrees (a plain number) to sin.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
float height(float elevation_degrees) {
#ifndef FIXED
  return safegi::sin(elevation_degrees);
#else
  return safegi::sin(elevation_degrees * units::degree);
#endif
}
}  // namespace cf

int main() { return 0; }
