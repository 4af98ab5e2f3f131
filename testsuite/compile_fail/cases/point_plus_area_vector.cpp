// Moving a point by a vector that is not a length.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> f(point<spaces::world> p, vector<spaces::world, dim::area> v, quantity<dim::length> d) {
  (void)d;
#ifndef FIXED
  return p + v;
#else
  return p + v / d;
#endif
}
}  // namespace cf

int main() { return 0; }
