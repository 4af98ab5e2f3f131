// Offsetting a displacement by a normal without the offset's length: v + n, where
// v + n * epsilon was meant (a unit vector is dimensionless; a displacement is a length).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/units.hpp>
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
vector<spaces::world> offset(vector<spaces::world> v, normal<spaces::world> n) {
#ifndef FIXED
  return v + n;
#else
  return v + n * (real(1e-4) * units::metre);
#endif
}
}  // namespace cf

int main() { return 0; }
